// Text output of the DEM exports (LAMMPS, LIGGGHTS, YADE fragments; CSV and JSON tables).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "corlab/dem/contact_ode.hpp"
#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/hysteresis_chi.hpp"
#include "corlab/version.hpp"

namespace corlab::dem {
namespace {

std::string pair_name(const PairCalibration& p) {
  return p.type_j == 0 ? fmt::format("{}-wall", p.type_i)
                       : fmt::format("{}-{}", p.type_i, p.type_j);
}

std::string fit_comment(const CurveFit& fit) {
  return fmt::format("fit over {:.4g}..{:.4g} m/s ({} speeds): rms {:.2e}, max |de| {:.2e}",
                     fit.velocities.front(), fit.velocities.back(), fit.velocities.size(),
                     fit.rms_error, fit.max_abs_error);
}

std::string header(const ExportSpec& spec, std::string_view code) {
  std::string out =
      fmt::format("# corlab {} dem export for {} (SI units). Particle types:\n", kVersion, code);
  for (std::size_t i = 0; i < spec.types.size(); ++i) {
    out += fmt::format("#   type {}: {} radius {:.6g} m\n", i + 1, spec.types[i].material.name,
                       spec.types[i].radius);
  }
  if (spec.wall) out += fmt::format("#   wall: {} (rigid, flat)\n", spec.wall->name);
  return out;
}

// e of the fitted viscoelastic law at v (ODE), for the tables.
double viscoelastic_e(const PairCalibration& p, double v) {
  const ViscoelasticHertzLaw law{p.hertz_stiffness, p.viscoelastic->parameter};
  const ForceLaw f = [&law](double d, double r, const ContactHistory&) { return law.force(d, r); };
  return simulate_impact(f, p.effective_mass, v).restitution;
}

double liggghts_e(const PairCalibration& p, double v) {
  const LiggghtsThorntonNingLaw law{
      {p.effective_modulus, p.effective_radius, p.liggghts->parameter}};
  const ForceLaw f = [&law](double d, double, const ContactHistory& h) { return law.force(d, h); };
  return simulate_impact(f, p.effective_mass, v).restitution;
}

std::vector<double> table_speeds(const ExportSpec& spec, int points) {
  std::vector<double> v(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i) {
    v[static_cast<std::size_t>(i)] = spec.v_min + (spec.v_max - spec.v_min) * i / (points - 1);
  }
  return v;
}

}  // namespace

std::string write_lammps(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
  std::string out = header(spec, "LAMMPS (pair_style granular, tested with 29Sep2021 / Debian 12)");
  out +=
      "# Needs: units si, atom_style sphere, comm_modify vel yes, fix nve/sphere.\n"
      "# Normal model `hertz` with kn = 4/3 E* [Pa]: F = kn sqrt(R* delta) delta (exact Hertz).\n"
      "# `hertz/material` is avoided: this LAMMPS's fix wall/gran uses about E/(2(1-nu)) for the\n"
      "# wall, neither rigid nor the same material. Tangential: frictionless (edit as needed).\n";
  if (spec.restitution) {
    out += fmt::format(
        "# Target: constant e = {:.6g}. `damping tsuji` maps its input e_in to alpha with a\n"
        "# polynomial that is not exact for this law (asked 0.3 it delivers 0.440), so e_in is\n"
        "# pre-compensated: alpha(e_in) = the exact alpha(e) = {:.8g} (corlab ODE).\n",
        *spec.restitution, pairs.front().tsuji_alpha);
  } else {
    out +=
        "# Target: velocity-dependent e(v). `damping viscoelastic` (F_d = eta a m* delta_dot,\n"
        "# a = sqrt(R* delta)) gives an e that falls with v (Schwager-Poeschel 2008); eta is "
        "fitted\n"
        "# per type pair to corlab's e(v) by least squares on ODE solutions of the same law.\n";
  }
  out += spec.wall_only ? "# wall-only export: no particle-particle pair_coeff\n"
                        : "pair_style granular\n";
  for (const auto& p : pairs) {
    if (p.type_j == 0) continue;
    const double kn = 4.0 / 3.0 * p.effective_modulus;
    if (spec.restitution) {
      out += fmt::format(
          "pair_coeff {} {} hertz {:.10g} {:.10g} tangential linear_nohistory 0.0 0.0 damping "
          "tsuji\n",
          p.type_i, p.type_j, kn, p.lammps_tsuji_input);
    } else {
      out += fmt::format("# {} : {}; {}\n", pair_name(p), p.target, fit_comment(*p.viscoelastic));
      out += fmt::format(
          "pair_coeff {} {} hertz {:.10g} {:.10g} tangential linear_nohistory 0.0 0.0 damping "
          "viscoelastic\n",
          p.type_i, p.type_j, kn, p.lammps_viscoelastic_eta());
    }
  }
  for (const auto& p : pairs) {
    if (p.type_j != 0) continue;
    const double kn = 4.0 / 3.0 * p.effective_modulus;
    const double damp = spec.restitution ? p.lammps_tsuji_input : p.lammps_viscoelastic_eta();
    if (!spec.restitution) {
      out += fmt::format("# {} : {}; {}\n", pair_name(p), p.target, fit_comment(*p.viscoelastic));
    }
    out += fmt::format("group corlab_type{0} type {0}\n", p.type_i);
    out += fmt::format(
        "fix corlab_wall{0} corlab_type{0} wall/gran granular hertz {1:.10g} {2:.10g} tangential "
        "linear_nohistory 0.0 0.0 damping {3} zplane 0.0 NULL\n",
        p.type_i, kn, damp, spec.restitution ? "tsuji" : "viscoelastic");
  }
  return out;
}

std::string write_liggghts(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
  std::string out = header(spec, "LIGGGHTS 3.8 (pair_style gran)");
  const std::size_t n = spec.types.size() + (spec.wall ? 1 : 0);
  const auto wall_type = spec.types.size() + 1;
  std::string young = "fix m1 all property/global youngsModulus peratomtype";
  std::string poisson = "fix m2 all property/global poissonsRatio peratomtype";
  for (const auto& t : spec.types) {
    young += fmt::format(" {:.10g}", t.material.youngs_modulus);
    poisson += fmt::format(" {:.6g}", t.material.poisson_ratio);
  }
  if (spec.wall) {
    young += fmt::format(" {:.10g}", spec.wall->youngs_modulus);
    poisson += fmt::format(" {:.6g}", spec.wall->poisson_ratio);
    out += fmt::format(
        "# The wall (plane z = 0; edit the geometry) uses atom type {} (its material).\n",
        wall_type);
  }
  out += young + "\n" + poisson + "\n";
  std::string matrix;
  if (spec.restitution) {
    out += fmt::format(
        "# Constant e = {:.6g}: model hertz maps e to damping 2 sqrt(5/6) |beta| sqrt(S_n m*),\n"
        "# beta = ln e/sqrt(ln^2 e + pi^2), exact for Hertz while the force is not clamped\n"
        "# (keep limitForce off). No pre-compensation needed.\n",
        *spec.restitution);
    matrix = fmt::format("fix m3 all property/global coefficientRestitution peratomtypepair {}", n);
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = 0; b < n; ++b) matrix += fmt::format(" {:.8g}", *spec.restitution);
    }
    out += matrix + "\n";
    out += fmt::format("fix m4 all property/global coefficientFriction peratomtypepair {} {}\n", n,
                       fmt::join(std::vector<std::string>(n * n, "0.0"), " "));
    out += "pair_style gran model hertz tangential no_history\npair_coeff * *\n";
    if (spec.wall) {
      out += fmt::format(
          "fix corlab_wall all wall/gran model hertz tangential no_history primitive "
          "type {} zplane 0.0\n",
          wall_type);
    }
    return out;
  }
  out +=
      "# e(v): model thornton_ning without adhesion (surfaceEnergy 0). LIGGGHTS yields at contact\n"
      "# radius a_y = coefficientYieldRatio r_i and unloads with the loading radius (not "
      "Thornton's\n"
      "# R_p); corlab fits the yield ratio on ODE solutions of exactly that law. The ratio is per\n"
      "# atom type: each type takes its wall fit (else its same-type fit).\n";
  std::string ratio = "fix m5 all property/global coefficientYieldRatio peratomtype";
  for (std::size_t t = 1; t <= spec.types.size(); ++t) {
    const PairCalibration* chosen = nullptr;
    for (const auto& p : pairs) {
      if (p.type_i == static_cast<int>(t) && (p.type_j == 0 || (!chosen && p.type_j == p.type_i))) {
        chosen = &p;
      }
    }
    ratio += fmt::format(" {:.10g}", chosen->liggghts_yield_ratio());
    out += fmt::format("# type {} ({}): {}; {}\n", t, pair_name(*chosen), chosen->target,
                       fit_comment(*chosen->liggghts));
  }
  if (spec.wall) ratio += " 0.5";  // the wall type's own ratio is never read for a primitive wall
  out += ratio + "\n";
  out += fmt::format("fix m6 all property/global surfaceEnergy peratomtypepair {} {}\n", n,
                     fmt::join(std::vector<std::string>(n * n, "0.0"), " "));
  matrix = fmt::format("fix m3 all property/global coefficientRestitution peratomtypepair {}", n);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b) matrix += " 0.9";  // read (betaeff) but unused normally
  }
  out += matrix + "\n";
  out += fmt::format("fix m4 all property/global coefficientFriction peratomtypepair {} {}\n", n,
                     fmt::join(std::vector<std::string>(n * n, "0.0"), " "));
  out += "pair_style gran model thornton_ning tangential no_history\npair_coeff * *\n";
  if (spec.wall) {
    out += fmt::format(
        "fix corlab_wall all wall/gran model thornton_ning tangential no_history "
        "primitive type {} zplane 0.0\n",
        wall_type);
  }
  return out;
}

std::string write_yade(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
  std::string out = header(spec, "YADE (2023.02a), Python: exec() it in a YADE script");
  out +=
      "# Hertz-Mindlin: Ip2_FrictMat_FrictMat_MindlinPhys maps en to its damping exactly for\n"
      "# Hertz (measured: en 0.3 -> 0.3002, 0.5 -> 0.49999). Use corlab_ip2 in the "
      "InteractionLoop\n"
      "# with Law2_ScGeom_MindlinPhys_Mindlin().\n"
      "from yade import *\n"
      "corlab_type_of_material = {}\n";
  for (std::size_t i = 0; i < spec.types.size(); ++i) {
    const auto& m = spec.types[i].material;
    out += fmt::format(
        "corlab_mat{0} = O.materials.append(FrictMat(young={1:.10g}, poisson={2:.6g}, "
        "density={3:.8g}, frictionAngle=0.0, label='{4}'))\ncorlab_type_of_material[corlab_mat{0}] "
        "= "
        "{0}\n",
        i + 1, m.youngs_modulus, m.poisson_ratio, m.density, m.name);
  }
  if (spec.wall) {
    out += fmt::format(
        "corlab_wall_mat = O.materials.append(FrictMat(young={:.10g}, poisson={:.6g}, "
        "density={:.8g}, frictionAngle=0.0, label='{}'))\ncorlab_type_of_material[corlab_wall_mat] "
        "= 0\n",
        spec.wall->youngs_modulus, spec.wall->poisson_ratio, spec.wall->density, spec.wall->name);
  }
  if (spec.restitution) {
    out += fmt::format("corlab_ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en={:.8g})\n",
                       *spec.restitution);
    return out;
  }
  out +=
      "# e(v): a per-contact hook. Add PyRunner(command='corlab_set_en()', iterPeriod=1) to\n"
      "# O.engines just before the InteractionLoop: it sets corlab_ip2.en from the approach speed "
      "of\n"
      "# the contacts about to form (e(v) tables below, linear in v, end values outside). Exact "
      "when\n"
      "# the contacts that form in the same time step share one impact speed (else the last "
      "wins).\n"
      "corlab_ev = {\n";
  for (const auto& p : pairs) {
    std::string vs;
    std::string es;
    for (const double v : table_speeds(spec, 64)) {
      vs += fmt::format("{:.8g}, ", v);
      es += fmt::format("{:.8g}, ", p.curve(v));
    }
    out += fmt::format("    ({}, {}): ([{}], [{}]),\n", p.type_i, p.type_j, vs, es);
  }
  out +=
      "}\n"
      "corlab_ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en=0.5)\n"
      "def corlab_e_of_v(key, v):\n"
      "    import numpy\n"
      "    vs, es = corlab_ev[key]\n"
      "    return float(numpy.interp(v, vs, es))\n"
      "def corlab_set_en():\n"
      "    for i in O.interactions.all():\n"
      "        if i.isReal:\n"
      "            continue\n"
      "        b1, b2 = O.bodies[i.id1], O.bodies[i.id2]\n"
      "        t1 = corlab_type_of_material.get(b1.material.id)\n"
      "        t2 = corlab_type_of_material.get(b2.material.id)\n"
      "        if t1 is None or t2 is None:\n"
      "            continue\n"
      "        dv = b1.state.vel - b2.state.vel\n"
      "        if isinstance(b1.shape, Sphere) and isinstance(b2.shape, Sphere):\n"
      "            n = b2.state.pos - b1.state.pos\n"
      "            speed = dv.dot(n) / n.norm()\n"
      "        else:\n"
      "            speed = dv.norm()\n"
      "        key = (max(t1, t2), 0) if min(t1, t2) == 0 else (min(t1, t2), max(t1, t2))\n"
      "        if speed > 0 and key in corlab_ev:\n"
      "            corlab_ip2.en = corlab_e_of_v(key, speed)\n";
  return out;
}

std::string write_table_csv(const ExportSpec& spec,
                            const std::vector<PairCalibration>& pairs,
                            int points) {
  std::string out = "# corlab dem e(v) table: linear interpolation in v, end values outside\n";
  out += "pair,velocity_m_s,e_target,chi_exact,e_lammps_viscoelastic,e_liggghts_thornton_ning\n";
  for (const auto& p : pairs) {
    for (const double v : table_speeds(spec, points)) {
      const double e = p.curve(v);
      out += fmt::format("{},{:.8g},{:.8g},{:.8g},{},{}\n", pair_name(p), v, e,
                         exact_chi(std::min(e, 1.0)),
                         p.viscoelastic ? fmt::format("{:.8g}", viscoelastic_e(p, v)) : "",
                         p.liggghts ? fmt::format("{:.8g}", liggghts_e(p, v)) : "");
    }
  }
  return out;
}

std::string write_json(const ExportSpec& spec,
                       const std::vector<PairCalibration>& pairs,
                       int points) {
  nlohmann::json root;
  root["corlab_version"] = std::string(kVersion);
  root["units"] = "SI (m, kg, s, N, Pa)";
  root["interpolation"] =
      "linear in velocity between table rows; end values outside [v_min, v_max]";
  const auto fit_json = [](const CurveFit& f) {
    return nlohmann::json{{"parameter", f.parameter},
                          {"rms_error", f.rms_error},
                          {"max_abs_error", f.max_abs_error},
                          {"velocities", f.velocities},
                          {"target", f.target},
                          {"fitted", f.fitted}};
  };
  for (const auto& p : pairs) {
    nlohmann::json j{{"pair", pair_name(p)},
                     {"target", p.target},
                     {"effective_modulus_Pa", p.effective_modulus},
                     {"effective_radius_m", p.effective_radius},
                     {"effective_mass_kg", p.effective_mass},
                     {"hertz_stiffness_N_per_m1.5", p.hertz_stiffness}};
    if (spec.restitution) {
      j["chi_exact"] = p.chi;
      j["tsuji_alpha_exact"] = p.tsuji_alpha;
      j["lammps_tsuji_input"] = p.lammps_tsuji_input;
    } else {
      j["viscoelastic_damping_N_s_per_m1.5"] = fit_json(*p.viscoelastic);
      j["lammps_viscoelastic_eta"] = p.lammps_viscoelastic_eta();
      j["thornton_limiting_pressure_Pa"] = fit_json(*p.thornton);
      j["liggghts_thornton_ning_pressure_Pa"] = fit_json(*p.liggghts);
      j["liggghts_yield_ratio"] = p.liggghts_yield_ratio();
    }
    nlohmann::json table = nlohmann::json::array();
    for (const double v : table_speeds(spec, points)) {
      const double e = p.curve(v);
      table.push_back({{"v", v}, {"e", e}, {"chi", exact_chi(std::min(e, 1.0))}});
    }
    j["table"] = table;
    root["pairs"].push_back(j);
  }
  return root.dump(2) + "\n";
}

}  // namespace corlab::dem
