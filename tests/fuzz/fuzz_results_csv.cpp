// Fuzz target: the results-CSV reader (read_results, what `corlab fit` and resume read) and the
// column accessors; once, the special and oversized files the reader refuses.
#include "corlab/core/text_file.hpp"
#include "corlab/study/results_table.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace corlab;
  static const bool special_files = [] {
    fuzz::expect_special_files_refused("results_csv", kMaxTableFileBytes,
                                       [](const auto& path) { (void)study::read_results(path); });
    return true;
  }();
  (void)special_files;
  const auto file = fuzz::scratch_file(".csv", data, size);
  fuzz::expect_clean("results_csv", [&] {
    const study::ResultsTable table = study::read_results(file);
    for (const auto& column : table.columns()) {
      if (table.is_numeric(column)) (void)table.numbers(column);
      (void)table.text(column);
    }
    if (table.has_column("status")) (void)table.where("status", "ok").size();
    if (table.has_column("case_id")) (void)table.sorted_by("case_id").size();
  });
  return 0;
}
