// The table of history columns (history_columns.hpp): one entry per column.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/history_columns.hpp"

#include <array>

namespace corlab::fem {
namespace {

/// A column that is the members `Row` of HistoryRow and ImpactHistory.
template <auto RowMember, auto SeriesMember>
constexpr HistoryColumn column(std::string_view name,
                               std::string_view unit,
                               std::string_view description,
                               int digits = 9) {
  return {name, unit, description, RowMember, SeriesMember, digits};
}

#define CORLAB_HISTORY_COLUMN(member, ...) \
  column<&HistoryRow::member, &ImpactHistory::member>(#member, __VA_ARGS__)

// The order is history.csv's column order.
const std::array kColumns{
    CORLAB_HISTORY_COLUMN(time, "s", "time since release at the gap"),
    CORLAB_HISTORY_COLUMN(contact_force, "N", "force of the substrate on the sphere"),
    CORLAB_HISTORY_COLUMN(indentation, "m", "sphere c.o.m. displacement since contact"),
    CORLAB_HISTORY_COLUMN(
        sphere_velocity,
        "m/s",
        "sphere c.o.m. velocity relative to the target's (a flat: the ground), + towards it"),
    CORLAB_HISTORY_COLUMN(kinetic_energy, "J", "kinetic energy of both bodies"),
    CORLAB_HISTORY_COLUMN(strain_energy, "J", "recoverable elastic strain energy"),
    CORLAB_HISTORY_COLUMN(plastic_dissipation, "J", "plastic work"),
    CORLAB_HISTORY_COLUMN(hourglass_energy, "J", "hourglass energy"),
    CORLAB_HISTORY_COLUMN(viscous_dissipation, "J", "bulk-viscosity dissipation"),
    CORLAB_HISTORY_COLUMN(contact_energy, "J", "penalty energy stored in the contact"),
    CORLAB_HISTORY_COLUMN(
        energy_balance_error, "-", "(sum of the energies - initial) / initial", 6),
};

#undef CORLAB_HISTORY_COLUMN

}  // namespace

std::span<const HistoryColumn> history_columns() { return kColumns; }

std::string history_csv_header(const HistoryColumn& column) {
  std::string out(column.name);
  if (column.unit == "-") return out;
  out += '_';
  for (const char c : column.unit) {
    if (c == '/') {
      out += "_per_";
    } else {
      out += c;
    }
  }
  return out;
}

void append_row(ImpactHistory& history, const HistoryRow& row) {
  for (const HistoryColumn& c : kColumns) (history.*c.series).push_back(row.*c.value);
}

}  // namespace corlab::fem
