// Fuzz target: the Gmsh mesh reader (read_gmsh on a .msh file); once, the special and oversized
// files it refuses before Gmsh sees them.
#include "corlab/core/text_file.hpp"
#include "corlab/fem/mesh/gmsh_reader.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace corlab;
  if (!fem::gmsh_available()) return 0;
  static const bool special_files = [] {
    fuzz::expect_special_files_refused("gmsh", kMaxMeshFileBytes,
                                       [](const auto& path) { (void)fem::read_gmsh(path); });
    return true;
  }();
  (void)special_files;
  const auto file = fuzz::scratch_file(".msh", data, size);
  fuzz::expect_clean("gmsh", [&] { (void)fem::read_gmsh(file); });
  return 0;
}
