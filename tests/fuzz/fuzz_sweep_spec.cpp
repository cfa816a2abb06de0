// Fuzz target: the sweep-spec reader (parse_sweep_spec) and the expansion into runs.
#include "corlab/study/sweep_spec.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  corlab::fuzz::expect_clean("sweep_spec", [&] {
    const auto spec = corlab::study::parse_sweep_spec(text, "fuzz.toml");
    (void)spec.expand();
    (void)spec.to_toml();
  });
  return 0;
}
