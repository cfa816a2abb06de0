#pragma once
/// @file fuzz_target.hpp
/// Shared by the fuzz targets (tests/fuzz/fuzz_*.cpp). Each target defines
/// LLVMFuzzerTestOneInput, so it links either with libFuzzer (clang -fsanitize=fuzzer, preset
/// `fuzz`) or with the deterministic mutation driver fuzz_driver.cpp (any compiler; what CI runs).
/// The property checked beyond "no crash, no hang": bad input is refused with an InputError whose
/// message is one line; any other exception escaping a reader is a finding (abort).

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "corlab/core/error.hpp"

namespace corlab::fuzz {

/// Runs `read`; an InputError with a one-line message is the expected refusal.
template <typename Read>
void expect_clean(std::string_view target, Read&& read) {
  try {
    read();
  } catch (const InputError& err) {
    const std::string_view message = err.what();
    if (message.find('\n') != std::string_view::npos || message.empty()) {
      std::fprintf(stderr, "%.*s: InputError message not one line: %s\n",
                   static_cast<int>(target.size()), target.data(), err.what());
      std::abort();
    }
  } catch (const std::exception& err) {
    std::fprintf(stderr, "%.*s: non-input exception escaped: %s\n", static_cast<int>(target.size()),
                 target.data(), err.what());
    std::abort();
  }
}

/// A per-process scratch file holding `data` (the readers under test take paths).
inline std::filesystem::path scratch_file(std::string_view suffix,
                                          const std::uint8_t* data,
                                          std::size_t size) {
  // In memory where there is a tmpfs: rewriting a disk file costs ~3 ms, a run of the fuzzer 10 s.
  static const std::filesystem::path dir = std::filesystem::is_directory("/dev/shm")
                                               ? std::filesystem::path("/dev/shm")
                                               : std::filesystem::temp_directory_path();
  const auto file = dir / ("corlab_fuzz_" + std::to_string(::getpid()) + std::string(suffix));
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file;
}

}  // namespace corlab::fuzz
