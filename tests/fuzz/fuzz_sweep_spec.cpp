// Fuzz target: the sweep-spec reader (parse_sweep_spec) and the expansion into runs; once, the
// special and oversized files load_sweep_spec refuses.
#include "corlab/core/text_file.hpp"
#include "corlab/study/sweep_spec.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool special_files = [] {
    corlab::fuzz::expect_special_files_refused(
        "sweep_spec", corlab::kMaxSpecFileBytes,
        [](const auto& path) { (void)corlab::study::load_sweep_spec(path); });
    return true;
  }();
  (void)special_files;
  const std::string text(reinterpret_cast<const char*>(data), size);
  corlab::fuzz::expect_clean("sweep_spec", [&] {
    const auto spec = corlab::study::parse_sweep_spec(text, "fuzz.toml");
    (void)spec.expand();
    (void)spec.to_toml();
  });
  return 0;
}
