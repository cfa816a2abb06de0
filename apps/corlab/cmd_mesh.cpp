// `corlab mesh`: generate (or read) the impact mesh of a case, write DIR/mesh.vtu and print the
// element counts, quality and explicit cost per body.
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/units.hpp"
#include "corlab/fem/config/impact_config.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/mesh/hex_mesh_generator.hpp"
#include "corlab/fem/mesh/mesh_generator.hpp"
#include "corlab/fem/mesh/mesh_quality.hpp"
#include "corlab/fem/output/vtu_writer.hpp"

namespace corlab::cli {
namespace {

struct MeshArgs {
  std::string config;
  std::vector<std::string> settings;
  std::string out;
};

void print_quality(const char* name, const fem::MeshQuality& q) {
  constexpr double kDeg = 1.0 / units::kDegree;
  fmt::print(
      "{:<10} elements {:>6}  nodes {:>6}  min_angle {:6.2f} deg  max_angle {:6.2f} deg  "
      "max_aspect {:6.2f}  min_jacobian {:.3e} m^2  min_char_length {:.4e} m  min_width {:.4e} m  "
      "edge [{:.4e}, "
      "{:.4e}] m  area {:.6e} m^2  volume {:.6e} m^3\n",
      name, q.elements, q.nodes, q.min_angle * kDeg, q.max_angle * kDeg, q.max_aspect_ratio,
      q.min_jacobian, q.min_characteristic_length, q.min_width, q.min_edge, q.max_edge, q.area,
      q.volume);
}

// The element updates per base step of each body under the default subcycling (geometry only):
// where a run's cost is.
void print_explicit_cost(const fem::Mesh& mesh,
                         const fem::MeshQuality& sphere,
                         const fem::MeshQuality& substrate) {
  const double shortest =
      std::min(sphere.min_characteristic_length, substrate.min_characteristic_length);
  fmt::print("explicit cost (element updates per base step; elements at subcycling levels 0-{})\n",
             fem::kCostLevels);
  for (const auto& [name, body] :
       {std::pair{"sphere", fem::Body::kSphere}, std::pair{"substrate", fem::Body::kSubstrate}}) {
    const fem::ExplicitCost c = fem::explicit_cost(mesh, body, shortest);
    fmt::print("{:<10} updates {:>8.1f}  levels {}\n", name, c.updates,
               fmt::join(c.elements_at_level, " "));
  }
}

// The 3-D model's mesh: its options, element counts and DIR/mesh.vtu.
int write_hex_mesh(const fem::ImpactConfig& config, const std::string& out) {
  const fem::HexMeshOptions o = fem::hex_mesh_options_for(config);
  const fem::HexMesh mesh = fem::build_hex_impact_mesh(config);
  int sphere = 0;
  for (const fem::Body b : mesh.element_body) sphere += b == fem::Body::kSphere ? 1 : 0;
  fmt::print(
      "3-D model: h {:.4e} m  zone radius {:.4e} m  zone depth {:.4e} m  travel {:.4e} m  "
      "growth {}  h_max {:.4e} m\n"
      "total      elements {:>6} (sphere {}, substrate {})  nodes {:>6}  symmetry {}  base {}  "
      "sphere_surface {}  top faces {}\n",
      o.h_contact, o.zone_radius, o.zone_depth, o.travel, o.growth, o.h_max, mesh.num_elements(),
      sphere, mesh.num_elements() - sphere, mesh.num_nodes(), mesh.symmetry_nodes.size(),
      mesh.base_nodes.size(), mesh.sphere_surface_nodes.size(), mesh.top_faces.size());
  std::filesystem::create_directories(out);
  const auto file = std::filesystem::path(out) / "mesh.vtu";
  fem::write_vtu(file, mesh);
  fmt::print(stderr, "wrote {}\n", file.string());
  return 0;
}

int run_mesh(const MeshArgs& args) {
  fem::ImpactConfig config =
      args.config.empty() ? fem::ImpactConfig{} : fem::load_impact_config(args.config);
  fem::apply_settings(config, args.settings, "--set");
  fem::validate(config);
  if (fem::uses_3d_model(config)) return write_hex_mesh(config, args.out);
  const fem::Mesh mesh = fem::build_impact_mesh(config);
  if (config.mesh.file.empty()) {
    const fem::MeshOptions o = fem::mesh_options_for(config);
    fmt::print(
        "predicted contact radius {:.4e} m (Hertz {:.4e} m)  h {:.4e} m  zone radius {:.4e} m  "
        "zone depth {:.4e} m  growth {}  h_max {:.4e} m\n",
        fem::predicted_contact_radius(config), fem::hertz_reference(config).contact_radius,
        o.h_contact, o.zone_radius, o.zone_depth, o.growth, o.h_max);
  }
  const fem::MeshQuality sphere = fem::mesh_quality(mesh, fem::Body::kSphere);
  const fem::MeshQuality substrate = fem::mesh_quality(mesh, fem::Body::kSubstrate);
  print_quality("sphere", sphere);
  print_quality("substrate", substrate);
  fmt::print(
      "total      elements {:>6}  nodes {:>6}  axis {}  base {}  sphere_surface {}  "
      "substrate_surface {}\n",
      mesh.num_elements(), mesh.num_nodes(), mesh.axis_nodes.size(), mesh.base_nodes.size(),
      mesh.sphere_surface_nodes.size(), mesh.substrate_surface_nodes.size());
  print_explicit_cost(mesh, sphere, substrate);
  std::filesystem::create_directories(args.out);
  const auto file = std::filesystem::path(args.out) / "mesh.vtu";
  fem::write_vtu(file, mesh);
  fmt::print(stderr, "wrote {}\n", file.string());
  return 0;
}

const CommandRegistration kRegistration{Command{
    "mesh", "Generate the impact mesh of a case, write DIR/mesh.vtu and print its quality",
    [](CLI::App& sub) -> std::function<int()> {
      auto args = std::make_shared<MeshArgs>();
      sub.add_option("--config", args->config, "case file (TOML; a pipe such as <(...) too)");
      sub.add_option("--set", args->settings, "key=value over the case (repeatable)");
      sub.add_option("--out", args->out, "output directory")->required();
      return [args] { return run_mesh(*args); };
    },
    40}};

}  // namespace
}  // namespace corlab::cli
