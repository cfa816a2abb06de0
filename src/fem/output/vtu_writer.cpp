// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/output/vtu_writer.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <fstream>
#include <string_view>

#include "corlab/core/error.hpp"

namespace corlab::fem {
namespace {

void check_field(const VtuField& f, int count, std::string_view kind) {
  if (f.components < 1 ||
      f.values.size() != static_cast<std::size_t>(f.components) * static_cast<std::size_t>(count))
    throw InputError(fmt::format("invalid vtu {} field \"{}\": {} values for {} x {} expected",
                                 kind, f.name, f.values.size(), f.components, count));
}

void write_array(std::ofstream& out, const VtuField& f) {
  out << fmt::format(
      "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" "
      "format=\"ascii\">\n",
      f.name, f.components);
  const std::size_t per_line = static_cast<std::size_t>(f.components) * 4;
  for (std::size_t k = 0; k < f.values.size(); ++k) {
    out << fmt::format("{:.9g}", f.values[k]) << ((k + 1) % per_line == 0 ? '\n' : ' ');
  }
  out << "\n        </DataArray>\n";
}

}  // namespace

namespace {

// One unstructured grid of cells with `per_cell` nodes of VTK type `vtk_type`: points at
// point(k) (3 coordinates [m]), cell e's nodes at cell(e), a "body" cell field first.
template <class Point, class Cell>
void write_grid(const std::filesystem::path& file,
                int nn,
                Point point,
                const std::vector<Body>& element_body,
                Cell cell,
                int per_cell,
                int vtk_type,
                const std::vector<VtuField>& point_fields,
                const std::vector<VtuField>& cell_fields) {
  const int ne = static_cast<int>(element_body.size());
  for (const auto& f : point_fields) check_field(f, nn, "point");
  for (const auto& f : cell_fields) check_field(f, ne, "cell");
  std::ofstream out(file);
  if (!out) throw InputError("invalid output file = " + file.string() + ": cannot be written");
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
         "  <UnstructuredGrid>\n";
  out << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", nn, ne);
  out << "      <Points>\n"
         "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int n = 0; n < nn; ++n) {
    const auto p = point(static_cast<std::size_t>(n));
    out << fmt::format("{:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
  }
  out << "        </DataArray>\n      </Points>\n      <Cells>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (int e = 0; e < ne; ++e)
    out << fmt::format("{}\n", fmt::join(cell(static_cast<std::size_t>(e)), " "));
  out << "        </DataArray>\n"
         "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (int e = 0; e < ne; ++e) out << per_cell * (e + 1) << ((e + 1) % 16 == 0 ? '\n' : ' ');
  out << "\n        </DataArray>\n"
         "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (int e = 0; e < ne; ++e) out << vtk_type << ((e + 1) % 32 == 0 ? '\n' : ' ');
  out << "\n        </DataArray>\n      </Cells>\n";
  out << "      <PointData>\n";
  for (const auto& f : point_fields) write_array(out, f);
  out << "      </PointData>\n      <CellData>\n";
  VtuField body{"body", 1, {}};
  body.values.reserve(static_cast<std::size_t>(ne));
  for (const Body b : element_body) body.values.push_back(b == Body::kSphere ? 0.0 : 1.0);
  write_array(out, body);
  for (const auto& f : cell_fields) write_array(out, f);
  out << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  if (!out) throw InputError("invalid output file = " + file.string() + ": write failed");
}

constexpr int kVtkQuad = 9;
constexpr int kVtkHexahedron = 12;

}  // namespace

void write_vtu(const std::filesystem::path& file,
               const Mesh& mesh,
               const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields) {
  write_grid(
      file, mesh.num_nodes(),
      [&](std::size_t k) {
        return std::array<double, 3>{mesh.r[k], mesh.z[k], 0.0};
      },
      mesh.element_body, [&](std::size_t e) { return mesh.quads[e]; }, 4, kVtkQuad, point_fields,
      cell_fields);
}

void write_vtu(const std::filesystem::path& file,
               const HexMesh& mesh,
               const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields) {
  write_grid(
      file, mesh.num_nodes(),
      [&](std::size_t k) {
        return std::array<double, 3>{mesh.x[k], mesh.y[k], mesh.z[k]};
      },
      mesh.element_body, [&](std::size_t e) { return mesh.hexes[e]; }, 8, kVtkHexahedron,
      point_fields, cell_fields);
}

namespace {

// The element fields of either snapshot, empty ones skipped.
std::vector<VtuField> stress_fields(const std::vector<double>& von_mises,
                                    const std::vector<double>& pressure,
                                    const std::vector<double>& plastic_strain) {
  std::vector<VtuField> cells;
  auto scalar_field = [&](const char* name, const std::vector<double>& a) {
    if (!a.empty()) cells.push_back(VtuField{name, 1, a});
  };
  scalar_field("von_mises", von_mises);
  scalar_field("pressure", pressure);
  scalar_field("plastic_strain", plastic_strain);
  return cells;
}

}  // namespace

void write_vtu(const std::filesystem::path& file, const FieldSnapshot& s) {
  std::vector<VtuField> points;
  auto vector_field = [&](const char* name, const std::vector<double>& a,
                          const std::vector<double>& b) {
    if (a.empty() || b.empty()) return;
    VtuField f{name, 3, {}};
    if (a.size() != b.size())
      throw InputError(fmt::format("invalid vtu point field \"{}\": component sizes {} != {}", name,
                                   a.size(), b.size()));
    f.values.reserve(3 * a.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      f.values.push_back(a[k]);
      f.values.push_back(b[k]);
      f.values.push_back(0.0);
    }
    points.push_back(std::move(f));
  };
  vector_field("displacement", s.displacement_r, s.displacement_z);
  vector_field("velocity", s.velocity_r, s.velocity_z);
  write_vtu(file, s.mesh, points, stress_fields(s.von_mises, s.pressure, s.plastic_strain));
}

void write_vtu(const std::filesystem::path& file, const HexFieldSnapshot& s) {
  std::vector<VtuField> points;
  if (!s.displacement.empty()) points.push_back(VtuField{"displacement", 3, s.displacement});
  if (!s.velocity.empty()) points.push_back(VtuField{"velocity", 3, s.velocity});
  write_vtu(file, s.mesh, points, stress_fields(s.von_mises, s.pressure, s.plastic_strain));
}

}  // namespace corlab::fem
