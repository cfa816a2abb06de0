// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file script_text.hpp
/// The one way user text (a table's file name, a material or model name, a label) enters the
/// generated DEM scripts (LAMMPS, LIGGGHTS, YADE): as data, never as code. Every writer passes such
/// text through these functions; the scripts copy the tables themselves, so no file name is ever
/// opened or run by them.
#include <string>
#include <string_view>

namespace corlab::dem::detail {

/// `text` as the scripts show it in a comment or a description: one line of printable ASCII with
/// no character that LAMMPS, LIGGGHTS or Python reads inside a comment line. Every byte outside
/// 0x20-0x7e and each of  " ' \ $ & #  is written \xNN: so no line break (a new command), no `&`
/// at a line's end (LAMMPS joins the next line to the comment), no `"""` (LAMMPS reads on to the
/// next one), no `$` (LAMMPS's variables). "r\xc3\xa9sultats.csv" for "résultats.csv".
std::string script_text(std::string_view text);

/// A Python string literal holding `text` (YADE's material labels): '...' around script_text's
/// form of it, which Python reads back byte for byte for ASCII text.
std::string python_string(std::string_view text);

}  // namespace corlab::dem::detail
