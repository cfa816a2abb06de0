#pragma once
/// @file fuzz_target.hpp
/// Shared by the fuzz targets (tests/fuzz/fuzz_*.cpp). Each target defines
/// LLVMFuzzerTestOneInput, so it links either with libFuzzer (clang -fsanitize=fuzzer, preset
/// `fuzz`) or with the deterministic mutation driver fuzz_driver.cpp (any compiler; what CI runs).
/// The property checked beyond "no crash, no hang": bad input is refused with an InputError whose
/// message is one line; any other exception escaping a reader is a finding (abort).

#include <unistd.h>

#include <chrono>
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

/// The special and oversized files every file reader refuses with a one-line InputError at once
/// (issue 31: `sweep /dev/zero` grew to 5 GB and ended in bad_alloc): /dev/zero, /dev/urandom, a
/// directory and a sparse file one byte over `cap` (no byte of it is read). Runs `read(path)` on
/// each; anything else (no error, another exception, more than a second) is a finding (abort).
template <typename Read>
void expect_special_files_refused(std::string_view target, std::size_t cap, Read&& read) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() /
                       ("corlab_fuzz_special_" + std::to_string(::getpid()) + std::string(target));
  fs::remove_all(dir);
  fs::create_directories(dir / "a_directory");
  const fs::path sparse = dir / "over_the_cap";
  { std::ofstream touch(sparse); }
  fs::resize_file(sparse, cap + 1);
  for (const fs::path& path :
       {fs::path("/dev/zero"), fs::path("/dev/urandom"), dir / "a_directory", sparse}) {
    const auto start = std::chrono::steady_clock::now();
    bool refused = false;
    expect_clean(target, [&] {
      try {
        read(path);
      } catch (const InputError&) {
        refused = true;
        throw;
      }
    });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!refused || seconds > 1.0) {
      std::fprintf(stderr, "%.*s: %s was %s in %.2f s\n", static_cast<int>(target.size()),
                   target.data(), path.c_str(), refused ? "refused" : "not refused", seconds);
      std::abort();
    }
  }
  fs::remove_all(dir);
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
