// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file text_file.hpp
/// The one way an input file reaches a parser: bounded, checked text. Every reader (config, sweep
/// spec, results CSV and `dem --table`, the materials database, the mesh file handed to Gmsh)
/// goes through here, so a special file (/dev/zero, /dev/urandom, a directory) is refused at once
/// instead of filling memory, and every reader treats a byte-order mark, invalid UTF-8 and NUL
/// bytes the same way. The caps are documented in docs/user/errors.md.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace corlab {

/// Largest config file (`--config`, `config_file=`) and materials database [bytes]: 1 MiB, some
/// thousand times a full config.
inline constexpr std::size_t kMaxConfigFileBytes = std::size_t{1} << 20;
/// Largest sweep spec [bytes]: 16 MiB, a grid of a million values written out; at worst (8 million
/// one-digit values) its TOML tree takes 0.7 GB before the run count refuses it in 1 s
/// (docs/user/errors.md).
inline constexpr std::size_t kMaxSpecFileBytes = std::size_t{16} << 20;
/// Largest results table (`corlab fit`, `dem --table`, `read_results`, a resumed results.csv)
/// [bytes]: 512 MiB, about a million rows of a sweep's results.csv.
inline constexpr std::size_t kMaxTableFileBytes = std::size_t{512} << 20;
/// Largest mesh file (`mesh.file`, read by Gmsh) [bytes]: 256 MiB.
inline constexpr std::size_t kMaxMeshFileBytes = std::size_t{256} << 20;

/// How read_text_file checks the content.
struct TextFileRules {
  std::size_t max_bytes = kMaxConfigFileBytes;  ///< more is refused (the check costs O(1) for a
                                                ///< regular file, max_bytes for a pipe)
  bool utf8 = true;  ///< refuse invalid UTF-8 and NUL bytes (off: a file this program wrote,
                     ///< e.g. results.csv cut by a kill inside a character)
};

/// The content of `file` without a leading UTF-8 byte-order mark. `what` names the input in the
/// one-line InputError, e.g. "config file": a file that cannot be opened, that is not a regular
/// file or a pipe (a directory, /dev/zero, a terminal), longer than rules.max_bytes, or (when
/// rules.utf8) not UTF-8 text. Pipes and process substitution (`--config <(...)`) are read up to
/// the cap.
std::string read_text_file(const std::filesystem::path& file,
                           std::string_view what,
                           const TextFileRules& rules = {});

/// For a reader that opens the file itself (Gmsh): InputError unless `file` is a regular file of
/// at most `max_bytes`.
void require_regular_file(const std::filesystem::path& file,
                          std::string_view what,
                          std::size_t max_bytes);

/// Offset of the first byte of `text` that is not part of valid UTF-8 (overlong forms, surrogates
/// and code points above U+10FFFF are invalid), or std::string_view::npos.
std::size_t invalid_utf8_offset(std::string_view text);

/// "512 MiB", "16 MiB", "1 MiB", "300 bytes": a byte count for messages.
std::string byte_size_text(std::size_t bytes);

}  // namespace corlab
