// Fuzz target: the inline material parser (`sphere.material = "steel_ma2023,sy=7e8"`,
// `--sphere E=..,nu=..`).
#include "corlab/materials/material_database.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string spec(reinterpret_cast<const char*>(data), size);
  corlab::fuzz::expect_clean("material_spec",
                             [&] { (void)corlab::parse_material_spec(spec, "sphere"); });
  return 0;
}
