// Bounded, checked input files (text_file.hpp): special files, caps, pipes, UTF-8, BOM (issue 31
// item 1: `sweep /dev/zero`, `fit /dev/zero` grew to 5 GB and ended in bad_alloc).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/text_file.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <string>
#include <thread>

#include "support/input_errors.hpp"
#include "support/scratch_files.hpp"

namespace corlab {
namespace {

using test::input_error_message;

TEST(ReadTextFile, ReadsAFileAndDropsAByteOrderMark) {
  const auto dir = test::fresh_dir("bom");
  test::spit(dir / "plain.toml", "a = 1\n");
  test::spit(dir / "bom.toml",
             "\xEF\xBB\xBF"
             "a = 1\n");
  EXPECT_EQ(read_text_file(dir / "plain.toml", "config file"), "a = 1\n");
  EXPECT_EQ(read_text_file(dir / "bom.toml", "config file"), "a = 1\n");
  test::spit(dir / "empty.toml", "");
  EXPECT_EQ(read_text_file(dir / "empty.toml", "config file"), "");  // the parser decides
}

TEST(ReadTextFile, RefusesSpecialFilesAtOnce) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(input_error_message([] { (void)read_text_file("/dev/zero", "spec"); }),
            "invalid spec = '/dev/zero': must be a regular file or a pipe (it is a character "
            "device)");
  EXPECT_EQ(input_error_message([] { (void)read_text_file("/dev/urandom", "results file"); }),
            "invalid results file = '/dev/urandom': must be a regular file or a pipe (it is a "
            "character device)");
  const auto dir = test::fresh_dir("special");
  EXPECT_EQ(input_error_message([&] { (void)read_text_file(dir, "config file"); }),
            "invalid config file = '" + dir.string() +
                "': must be a regular file or a pipe (it is a directory)");
  EXPECT_EQ(input_error_message([&] { (void)read_text_file(dir / "none", "config file"); }),
            "invalid config file = '" + (dir / "none").string() +
                "': must be a readable file (No such file or directory)");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

TEST(ReadTextFile, RefusesARegularFileOverTheCapBeforeReadingIt) {
  const auto dir = test::fresh_dir("cap");
  test::spit(dir / "big.csv", std::string(101, 'x'));
  EXPECT_EQ(input_error_message(
                [&] { (void)read_text_file(dir / "big.csv", "results file", {.max_bytes = 100}); }),
            "invalid results file = '" + (dir / "big.csv").string() +
                "': must be at most 100 bytes long (the cap of this input)");
  EXPECT_EQ(read_text_file(dir / "big.csv", "results file", {.max_bytes = 101}).size(), 101U);
  // A sparse file of 2 GiB is refused by its size, without a byte read.
  const auto sparse = dir / "sparse.csv";
  test::spit(sparse, "");
  std::filesystem::resize_file(sparse, std::uintmax_t{2} << 30);
  EXPECT_NE(input_error_message([&] {
              (void)read_text_file(sparse, "results file", {.max_bytes = kMaxTableFileBytes});
            }).find("must be at most 512 MiB long"),
            std::string::npos);
}

TEST(ReadTextFile, ReadsAPipeUpToTheCap) {
  std::signal(SIGPIPE, SIG_IGN);  // the writer meets a closed pipe once the reader refuses
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  std::thread writer([fd = fds[1]] {
    const std::string chunk(4096, 'y');
    for (int i = 0; i < 64; ++i) {  // 256 KiB: over a 100 KiB cap
      if (::write(fd, chunk.data(), chunk.size()) < 0) break;
    }
    ::close(fd);
  });
  const std::string path = "/dev/fd/" + std::to_string(fds[0]);
  const std::string msg = input_error_message(
      [&] { (void)read_text_file(path, "config file", {.max_bytes = std::size_t{100} * 1024}); });
  ::close(fds[0]);  // the writer then fails and stops
  writer.join();
  EXPECT_EQ(msg, "invalid config file = '" + path +
                     "': must be at most 102400 bytes long (the cap of this input)");

  ASSERT_EQ(::pipe(fds), 0);
  ASSERT_EQ(::write(fds[1], "[impact]\n", 9), 9);
  ::close(fds[1]);
  EXPECT_EQ(read_text_file("/dev/fd/" + std::to_string(fds[0]), "config file"), "[impact]\n");
  ::close(fds[0]);
}

TEST(ReadTextFile, AFifoWithoutAWriterReadsAsEmptyInsteadOfWaiting) {
  const auto fifo = test::fresh_dir("fifo") / "f";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(read_text_file(fifo, "config file"), "");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

TEST(ReadTextFile, RefusesNonUtf8AndNulBytesNamingTheLine) {
  const auto dir = test::fresh_dir("utf8");
  test::spit(dir / "latin1.csv", "case_id,status\nc1,fa\xFFiled\n");
  EXPECT_EQ(input_error_message([&] { (void)read_text_file(dir / "latin1.csv", "results file"); }),
            "invalid results file = '" + (dir / "latin1.csv").string() +
                "': must be UTF-8 text (line 2: byte 0xff is not valid UTF-8)");
  test::spit(dir / "nul.toml", std::string("a = 1\n\0", 7));
  EXPECT_EQ(input_error_message([&] { (void)read_text_file(dir / "nul.toml", "config file"); }),
            "invalid config file = '" + (dir / "nul.toml").string() +
                "': must be a text file (line 2 holds a NUL byte)");
  // A program's own file (a resumed results.csv cut inside a character) may skip the check.
  EXPECT_EQ(read_text_file(dir / "latin1.csv", "results file", {.utf8 = false}).size(), 26U);
  test::spit(dir / "utf8.csv", "name\nacier \xC3\xA0 ressort \xE2\x82\xAC \xF0\x9F\x98\x80\n");
  EXPECT_NO_THROW((void)read_text_file(dir / "utf8.csv", "results file"));
}

// Issue 42: a path with a NUL byte was read up to the NUL ("/tmp\0x": "it is a directory").
TEST(ReadTextFile, APathWithANulByteIsRefusedAsSuch) {
  const std::filesystem::path path(std::string("/tmp\0x", 6));
  EXPECT_EQ(
      input_error_message([&] { (void)read_text_file(path, "config file"); }),
      "invalid config file = '/tmp\\x00x': must be a path without a NUL byte (byte 4 is NUL)");
  EXPECT_EQ(input_error_message([&] { require_regular_file(path, "mesh.file", 1); }),
            "invalid mesh.file = '/tmp\\x00x': must be a path without a NUL byte (byte 4 is NUL)");
}

TEST(InvalidUtf8Offset, FindsTheFirstBadByte) {
  EXPECT_EQ(invalid_utf8_offset("plain ascii"), std::string_view::npos);
  EXPECT_EQ(invalid_utf8_offset("\xC3\xA9t\xC3\xA9"), std::string_view::npos);
  EXPECT_EQ(invalid_utf8_offset("\xF4\x8F\xBF\xBF"), std::string_view::npos);  // U+10FFFF
  EXPECT_EQ(invalid_utf8_offset("ab\xFF"), 2U);
  EXPECT_EQ(invalid_utf8_offset("\xC0\x80"), 0U);          // overlong NUL
  EXPECT_EQ(invalid_utf8_offset("x\xE0\x80\x80"), 1U);     // overlong 3-byte form
  EXPECT_EQ(invalid_utf8_offset("\xED\xA0\x80"), 0U);      // a surrogate
  EXPECT_EQ(invalid_utf8_offset("\xF4\x90\x80\x80"), 0U);  // above U+10FFFF
  EXPECT_EQ(invalid_utf8_offset("ok\xE2\x82"), 2U);        // cut character
  EXPECT_EQ(invalid_utf8_offset("\x80"), 0U);              // a lone continuation byte
}

TEST(RequireRegularFile, RefusesWhatGmshShouldNotOpen) {
  const auto dir = test::fresh_dir("regular");
  test::spit(dir / "m.msh", "12345");
  EXPECT_NO_THROW(require_regular_file(dir / "m.msh", "mesh.file", 5));
  EXPECT_EQ(input_error_message([&] { require_regular_file(dir / "m.msh", "mesh.file", 4); }),
            "invalid mesh.file = '" + (dir / "m.msh").string() +
                "': must be at most 4 bytes long (the cap of this input)");
  EXPECT_EQ(input_error_message([] { require_regular_file("/dev/zero", "mesh.file", 4); }),
            "invalid mesh.file = '/dev/zero': must be a regular file (it is a character device)");
}

TEST(ByteSizeText, MiBWhenWhole) {
  EXPECT_EQ(byte_size_text(kMaxTableFileBytes), "512 MiB");
  EXPECT_EQ(byte_size_text(kMaxConfigFileBytes), "1 MiB");
  EXPECT_EQ(byte_size_text(300), "300 bytes");
}

}  // namespace
}  // namespace corlab
