// `corlab dem`: calibrate DEM contact laws to a constant e or an e(v) (model or FE table) and
// write LAMMPS, LIGGGHTS and YADE fragments plus e(v)/chi tables (CSV, JSON).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numeric>
#include <optional>
#include <vector>

#include "command.hpp"
#include "corlab/core/error.hpp"
#include "corlab/core/interrupt.hpp"
#include "corlab/core/number.hpp"
#include "corlab/core/output_directory.hpp"
#include "corlab/dataset/dem_fe_targets.hpp"
#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/tangential.hpp"
#include "corlab/materials/material_database.hpp"
#include "corlab/study/result_cache.hpp"
#include "corlab/study/results_table.hpp"

namespace corlab::cli {
namespace {

struct DemArgs {
  std::vector<std::string> types;        // [LABEL=]MATERIAL:RADIUS
  std::vector<std::string> walls;        // [LABEL=]MATERIAL[@SHAPE]
  std::vector<std::string> pairs;        // A/B=E
  std::vector<std::string> pair_tables;  // A/B=FILE
  std::optional<double> restitution;
  std::string model;
  std::string table;
  double v_min = 0.1;
  double v_max = 10.0;
  int fit_points = 9;
  int table_points = 64;
  bool wall_only = false;
  std::vector<std::string> friction;  // MU (every pair) or A/B=MU (repeat)
  double rolling = 0.0;               // rolling resistance mu_r [-] of every pair
  std::string out = "dem_export";
  int jobs = 0;           // --model fe|auto: speeds run at once (0: one per core)
  bool no_cache = false;  // --model fe|auto: compute every speed, store nothing
  bool quiet = false;     // --model fe|auto: no progress line
};

dem::ParticleType parse_type(const std::string& spec) {
  const auto colon = spec.rfind(':');
  if (colon == std::string::npos) {
    throw_invalid("type", spec, "[LABEL=]MATERIAL:RADIUS (radius in m)");
  }
  dem::ParticleType t;
  auto labelled = dem::parse_labelled_material(std::string_view(spec).substr(0, colon), "type");
  t.material = std::move(labelled.material);
  t.label = std::move(labelled.label);
  t.radius = parse_finite("type radius", std::string_view(spec).substr(colon + 1));
  require_positive("type radius", t.radius, "[m]");
  return t;
}

// e(v) from an FE results.csv (columns velocity, e; rows with status != ok are skipped).
dem::RestitutionCurve read_table(const std::string& file) {
  auto table = study::read_results(file);
  if (table.has_column("status")) table = table.where("status", "ok");
  const auto v = table.numbers("velocity");
  const auto e = table.numbers("e");
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return v[a] < v[b]; });
  std::vector<double> vs;
  std::vector<double> es;
  for (const auto i : order) {
    vs.push_back(v[i]);
    es.push_back(e[i]);
  }
  return dem::tabulated_curve(vs, es);
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) throw_invalid("--out", path.string(), "a writable directory");
  out << text;
}

// The spec of the arguments (the tables read), without the FE source of --model fe|auto.
dem::ExportSpec export_spec(const DemArgs& args) {
  dem::ExportSpec spec;
  for (const auto& t : args.types) spec.types.push_back(parse_type(t));
  for (const auto& w : args.walls) dem::add_wall(spec, w);
  for (const auto& p : args.pairs) spec.pair_restitution.push_back(dem::parse_pair_restitution(p));
  for (const auto& p : args.pair_tables) {
    auto table = dem::parse_pair_table(p);
    table.curve = read_table(table.source);
    spec.pair_tables.push_back(std::move(table));
  }
  spec.restitution = args.restitution;
  spec.model = args.model;
  if (!args.table.empty()) {
    spec.table = read_table(args.table);
    spec.table_source = args.table;
  }
  spec.v_min = args.v_min;
  spec.v_max = args.v_max;
  spec.fit_points = args.fit_points;
  spec.wall_only = args.wall_only;
  bool friction_given = false;
  for (const auto& f : args.friction) {
    if (f.find('/') != std::string::npos) {
      spec.pair_friction.push_back(dem::parse_pair_value(f, "friction"));
    } else if (friction_given) {
      throw_invalid("friction", f, "one MU for every pair (A/B=MU for single pairs)");
    } else {
      spec.friction = parse_finite("friction", f);
      friction_given = true;
    }
  }
  spec.rolling = args.rolling;
  return spec;
}

int run_dem(const DemArgs& args) {
  dem::ExportSpec spec = export_spec(args);
  dem::validate_table_points(args.table_points);
  // --model fe|auto: each pair's e(v) from the FE solver (dem_fe_targets.hpp), as predict's.
  std::optional<study::ResultCache> cache;
  const InterruptScope interrupt;
  if (!dem::is_external_model(spec.model) && (args.jobs != 0 || args.no_cache)) {
    throw_invalid(args.jobs != 0 ? "--jobs" : "--no-cache",
                  args.jobs != 0 ? std::to_string(args.jobs) : "true",
                  "unset unless --model fe or auto (the FE runs)");
  }
  if (dem::is_external_model(spec.model)) {
    if (!args.no_cache) {
      cache.emplace(study::default_cache_directory(), study::cache_build_id(),
                    [](const std::string& warning) {
                      std::fprintf(stderr, "corlab: warning: %s\n", warning.c_str());
                    });
    }
    spec.target_source =
        dataset::fe_pair_targets(spec.model, {.jobs = args.jobs,
                                              .cache = cache ? &*cache : nullptr,
                                              .progress = args.quiet ? nullptr : stderr,
                                              .cancel = interrupt.flag()});
  }
  // A pair a registered model does not cover (an elastic pair) is refused by calibrate_pairs
  // with the ways out (--model fe or auto, --pair, a yield stress, --wall-only); every wall
  // material's pairs and each pair's friction: calibrate_export.
  std::vector<dem::PairCalibration> pairs;
  try {
    pairs = dem::calibrate_export(spec);
  } catch (const InputError&) {
    if (!interrupt.requested()) throw;
    fmt::print(stderr, "corlab dem: interrupted ({}); finished FE speeds are cached\n",
               interrupt.signal_name());
    return interrupt.exit_code();
  }
  for (const auto& p : pairs) {
    for (const auto& w : p.warnings)
      std::fprintf(stderr, "corlab: warning: pair %s: %s\n", p.name().c_str(), w.c_str());
  }
  const std::filesystem::path dir(args.out);
  ensure_output_directory(dir, "--out");
  write_file(dir / "lammps.in", dem::write_lammps(spec, pairs));
  write_file(dir / "lammps_nopython.in", dem::write_lammps(spec, pairs, false));
  write_file(dir / "lammps_compiled.in", dem::write_lammps_compiled(spec, pairs));
  write_file(dir / "liggghts.in", dem::write_liggghts(spec, pairs));
  write_file(dir / "yade_fragment.py", dem::write_yade(spec, pairs));
  write_file(dir / "restitution_table.csv", dem::write_table_csv(spec, pairs, args.table_points));
  write_file(dir / "dem_export.json", dem::write_json(spec, pairs, args.table_points));
  for (const auto& [name, stl] : dem::wall_meshes(spec)) write_file(dir / name, stl);
  for (const auto& p : pairs) {
    const auto lammps = dem::lammps_delivery(spec, p, true);
    const auto lammps_plain = dem::lammps_delivery(spec, p, false);
    const auto liggghts = dem::liggghts_delivery(pairs, p);
    const auto yade = dem::yade_delivery(spec, p);
    fmt::print(
        "{}: {}\n    max |de|: LAMMPS {:.1e}, without Python {:.1e}, LIGGGHTS {:.1e}, YADE "
        "{:.1e}; contact time {:.3g} s at {} m/s\n",
        p.name(), p.target, lammps.max_abs_error, lammps_plain.max_abs_error,
        liggghts.max_abs_error, yade.max_abs_error, p.contact_time_fast, spec.v_max);
    if (p.friction > 0.0) {
      fmt::print("    tangential: mu {:.6g}, Mindlin k_t = 8 G* a with 8 G* = {:.6g} Pa\n",
                 p.friction, dem::mindlin_coefficient(p.shear_modulus));
    }
  }
  fmt::print(
      "time step [s]: LAMMPS {:.3g}, without Python {:.3g}, LIGGGHTS {:.3g}, YADE {:.3g} "
      "(set in each fragment; e within {:.0e} of each law's)\n",
      dem::lammps_time_step(pairs, true), dem::lammps_time_step(pairs, false),
      dem::liggghts_time_step(pairs), dem::yade_time_step(pairs), dem::kTimeStepError);
  fmt::print(
      "wrote {}/{{lammps.in, lammps_nopython.in, lammps_compiled.in, liggghts.in, "
      "yade_fragment.py, restitution_table.csv, dem_export.json}}\n",
      dir.string());
  return 0;
}

const CommandRegistration kRegistration{Command{
    "dem", "Calibrate DEM contact laws to e or e(v); write LAMMPS/LIGGGHTS/YADE inputs and tables",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<DemArgs>();
      sub.add_option("--type", a->types,
                     "particle type [LABEL=]MATERIAL:RADIUS[m] (repeat; type ids 1, 2...)")
          ->required();
      sub.add_option(
          "--wall", a->walls,
          "[LABEL=]MATERIAL[@SHAPE] a wall (repeat): SHAPE plane:PX,PY,PZ,NX,NY,NZ[,HALF] "
          "(normal into the particles), cylinder:AXIS,C1,C2,R,LO,HI (particles inside) "
          "or floor (default, z = 0)");
      sub.add_option("--pair", a->pairs,
                     "A/B=E: constant e of one pair (type labels or ids, wall), e.g. an elastic "
                     "glass/glass=1 (repeat)");
      sub.add_option("--pair-table", a->pair_tables,
                     "A/B=FILE: e(v) of one pair from an FE results.csv (columns velocity, e), "
                     "e.g. of two spheres of those types (repeat)");
      auto* e = sub.add_option("--restitution", a->restitution, "constant target e in (0, 1)");
      auto* m = sub.add_option("--model", a->model,
                               "registered CoR model for e(v), e.g. thornton1997; fe (corlab's FE "
                               "solver per pair, cached) or auto (corlab2026p where accurate, "
                               "else the FE)");
      auto* t =
          sub.add_option("--table", a->table, "FE results.csv (columns velocity, e) for e(v)");
      e->excludes(m)->excludes(t);
      m->excludes(t);
      sub.add_option("--friction", a->friction,
                     "MU: Coulomb friction coefficient of every pair (default 0: frictionless), "
                     "A/B=MU: of one pair (repeat); above 0 the fragments add Mindlin's "
                     "tangential stiffness 8 G* a");
      sub.add_option("--rolling", a->rolling,
                     "rolling resistance coefficient mu_r of every pair (moment <= mu_r R* F_n; "
                     "default 0: none)");
      sub.add_option("--v-min", a->v_min, "lower end of the e(v) range [m/s]");
      sub.add_option("--v-max", a->v_max, "upper end of the e(v) range [m/s]");
      sub.add_option("--fit-points", a->fit_points, "speeds of the e(v) fits (log-uniform)");
      sub.add_option("--table-points", a->table_points,
                     "rows per pair of the output tables, in [2, 10000]");
      sub.add_option("--out", a->out, "output directory");
      sub.add_flag("--wall-only", a->wall_only, "only type-wall contacts (no particle pairs)");
      sub.add_option("--jobs", a->jobs, "fe|auto: speeds run at once (0: one per core)")
          ->check(CLI::Range(0, 4096));
      sub.add_flag("--no-cache", a->no_cache,
                   "fe|auto: compute every speed and store nothing (cache: `corlab cache`)");
      sub.add_flag("--quiet", a->quiet, "no progress line of the FE runs (fe|auto) on stderr");
      return [a] { return run_dem(*a); };
    },
    60}};

}  // namespace
}  // namespace corlab::cli
