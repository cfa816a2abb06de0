// Fuzz target: the Gmsh mesh reader (read_gmsh on a .msh file).
#include "corlab/fem/mesh/gmsh_reader.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace corlab;
  if (!fem::gmsh_available()) return 0;
  const auto file = fuzz::scratch_file(".msh", data, size);
  fuzz::expect_clean("gmsh", [&] { (void)fem::read_gmsh(file); });
  return 0;
}
