// Fuzz target: the dataset design's spec writer (issue 42). The input is the command line the spec
// names in its header (`corlab dataset design --out <path>`); the spec must read back, with the
// sweep reader, as exactly the design's cases whatever the path holds (a line break and a [grid]
// in it stay in the comment).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "corlab/dataset/dataset_spec.hpp"
#include "corlab/study/sweep_spec.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path(reinterpret_cast<const char*>(data), size);
  corlab::dataset::DatasetDesign design;
  design.points = 2;
  static const std::string expected = [&] {
    auto plain = corlab::study::parse_sweep_spec(
        corlab::dataset::dataset_spec_toml(design, "corlab"), "plain.toml");
    plain.toml_text.clear();  // regenerated from the fields: the cases, not the comment
    return plain.to_toml();
  }();
  corlab::fuzz::expect_clean("dataset_spec", [&] {
    const std::string text =
        corlab::dataset::dataset_spec_toml(design, "corlab dataset design --out " + path);
    auto spec = corlab::study::parse_sweep_spec(text, "fuzz.toml");
    spec.toml_text.clear();
    if (spec.expand().size() != 2 || spec.to_toml() != expected) {
      std::fprintf(stderr, "dataset_spec: the path changed the spec\n");
      std::abort();
    }
  });
  return 0;
}
