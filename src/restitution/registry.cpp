// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/registry.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "corlab/core/error.hpp"
#include "corlab/restitution/corlab2026p.hpp"

namespace corlab::restitution {

namespace {

constexpr const char* kMaCitation =
    "Ma J., Jie H., Bai M., Peng J., Chen H., Chen D. (2023) Chinese J. Theor. Appl. Mech. "
    "55(4):982-990, eqs. 12, 18, 19";
// The FE calibration of Ma et al. 2023 (steel E = 210 GPa, nu = 0.3 on both sides, so
// E* = E / (2 (1 - nu^2)); rho = 3925-15700 kg/m^3, v = 0.1-70 m/s, sigma_y = 300-1300 MPa) in
// k1 = E*/(rho v^2) and k2 = sigma_y/E*.
constexpr double kMaEStar = 210e9 / (2.0 * (1.0 - 0.3 * 0.3));
constexpr DimensionlessBox kMaCalibration{.k1_min = kMaEStar / (15700.0 * 70.0 * 70.0),
                                          .k1_max = kMaEStar / (3925.0 * 0.1 * 0.1),
                                          .k2_min = 300e6 / kMaEStar,
                                          .k2_max = 1300e6 / kMaEStar};
constexpr const char* kThorntonCitation =
    "Thornton C. (1997) J. Appl. Mech. 64:383-386 (closed form as quoted by Jackson, Green & "
    "Marghitu 2010, eq. 2)";
constexpr const char* kThorntonEquation =
    "e = sqrt(6 sqrt3/5) sqrt(1 - r^2/6) [r/(r + 2 sqrt(6/5 - r^2/5))]^(1/4), r = v_y/v; "
    "v_y = 1.5605 sqrt(p_y^5/(E*^4 rho)); e = 1 for v <= v_y";
constexpr const char* kThorntonNote =
    "confirmed (two sources): contact law, yield velocity and closed form; which p_y the seed "
    "paper used (1.6 sigma_y, C(nu) sigma_y or sigma_y) is unconfirmed";
constexpr const char* kJgCitation =
    "Jackson R.L., Green I., Marghitu D.B. (2010) Nonlinear Dyn. 60(3):217-229; loading law "
    "Jackson & Green (2005) J. Tribol. 127(2):343-354";
constexpr const char* kJgFitEquation =
    "e = 1 - 0.0361 eps^-0.114 ln(V') (V' - 1)^(9.5 eps), V' = v/V_c, "
    "V_c = 1.5605 (C S_y)^2.5/(E*^2 sqrt(rho)), C = 1.295 exp(0.736 nu); e = 1 for V' <= 1";

// corlab2026p's held-out RMS is <= 2 % on the random 20 % and both corners up to this damage
// number rho* v^2/sigma_y [-] (scripts/corlab2026p_scores.py, docs/theory/corlab_model.md;
// python/tests/test_model_fit.py checks it against the shipped datasets).
constexpr double kCorlab2026pAccurateDamageNumber = 0.003;

/// What a model is bound to besides the pair quantities: the options and both materials (a model
/// of a yielding sphere or of hardening reads them whole). `sphere` is the pair's reduced sphere
/// (density rho*, the sphere itself on a flat); `impactor` the sphere as given.
struct FactoryContext {
  const ModelOptions& options;
  const Material& sphere;
  const Material& substrate;
  const Material& impactor;
};

/// Builds a model's kernel for a material pair (`clamp` already resolved from the options).
using Factory = Model::Kernel (*)(const ImpactPair& pair, bool clamp, const FactoryContext& ctx);

/// One row of the registry: the model's metadata and its factory.
struct Registration {
  ModelInfo info;
  Factory factory;
};

void add_ma2023(std::vector<Registration>& r) {
  r.push_back(
      {ModelInfo{.name = "ma2023",
                 .title = "Ma et al. 2023 dimensionless log law",
                 .citation = kMaCitation,
                 .equation =
                     "e = 1.16 + 0.253 ln(sigma_y/E*) + 0.056 ln(E*/(rho v^2)) for v >= v_y, "
                     "v_y = sqrt(15.81 sigma_y^4.5/(rho E*^3.5)); e = 1 below; clamped to [0, 1]",
                 .validity = "FE calibration v = 0.1-70 m/s, sigma_y = 300-1300 MPa, E = 210 GPa, "
                             "rho = 3925-15700 kg/m^3; fit error within +-5 %",
                 .status = Status::kVerifiedPaper,
                 .status_note =
                     "confirmed (one source + derivation): the paper text; the derivation "
                     "reproduces 15.81 and the e = 1 crossing. Eq. 18's v_y differs from the exact "
                     "crossing (log branch 1.0003-1.0005 at v_y on the seed pairs, removed by the "
                     "clamp; for sigma_y/E* < ~0.0047 a downward step < ~1e-3 at v_y)",
                 .clamped_by_default = true,
                 .calibrated = kMaCalibration},
       [](const ImpactPair& pair, bool clamp, const FactoryContext&) -> Model::Kernel {
         return Ma2023{.pair = pair, .exact_crossing = false, .clamp = clamp};
       }});
  r.push_back(
      {ModelInfo{.name = "ma2023-exact",
                 .title = "Ma et al. 2023 with the exact crossing velocity v_y*",
                 .citation = kMaCitation,
                 .equation =
                     "e = 1 - 0.112 ln(v/v_y*) for v >= v_y*, "
                     "v_y* = sqrt(exp(0.16/0.056) (sigma_y/E*)^(0.253/0.056) E*/rho); e = 1 below",
                 .validity = "as ma2023; continuous, monotone and <= 1 by construction",
                 .status = Status::kVerifiedPaper,
                 .status_note =
                     "confirmed (one source + derivation): eq. 12 of the paper with the yield "
                     "velocity replaced by the exact e = 1 crossing (checked numerically)",
                 .clamped_by_default = true,
                 .calibrated = kMaCalibration},
       [](const ImpactPair& pair, bool clamp, const FactoryContext&) -> Model::Kernel {
         return Ma2023{.pair = pair, .exact_crossing = true, .clamp = clamp};
       }});
}

template <ThorntonPressure Pressure>
Model::Kernel thornton(const ImpactPair& pair, bool /*clamp*/, const FactoryContext& /*ctx*/) {
  return Thornton1997{.pair = pair, .pressure = Pressure};
}

void add_thornton1997(std::vector<Registration>& r) {
  const struct {
    const char* name;
    const char* title;
    const char* py;
    Factory factory;
  } variants[] = {
      {"thornton1997", "Thornton 1997, p_y = 1.6 sigma_y", "p_y = 1.6 sigma_y (default)",
       &thornton<ThorntonPressure::kHertzOnset>},
      {"thornton1997-cnu", "Thornton 1997, p_y = C(nu) sigma_y",
       "p_y = C(nu) sigma_y, C = 1.295 exp(0.736 nu)", &thornton<ThorntonPressure::kJacksonGreenC>},
      {"thornton1997-sy", "Thornton 1997, p_y = sigma_y", "p_y = sigma_y",
       &thornton<ThorntonPressure::kYieldStress>},
  };
  for (const auto& t : variants) {
    r.push_back(
        {ModelInfo{.name = t.name,
                   .title = t.title,
                   .citation = kThorntonCitation,
                   .equation = fmt::format("{}; {}", kThorntonEquation, t.py),
                   .validity =
                       "quasi-static elastic-perfectly plastic contact, any v > 0; known to "
                       "under-predict e for metals",
                   .status = Status::kVerifiedSecondSource,
                   .status_note = kThorntonNote,
                   .clamped_by_default = true},
         t.factory});
  }
}

void add_jackson_green2010(std::vector<Registration>& r) {
  r.push_back(
      {ModelInfo{
           .name = "jg1",
           .title = "Jackson-Green-Marghitu 2010 J-G1 (Etsion 2005 unloading)",
           .citation = std::string(kJgCitation) +
                       "; unloading Etsion, Kligerman & Kadin (2005) Int. J. Solids Struct. "
                       "42(13):3716-3729",
           .equation = "e^2 = W_unload/W_load, W_load = int_0^w_max P_JG2005 dw = m v^2/2, "
                       "W_unload = P_max (w_max - w_res)/(n + 1), n = 1.5 w*^-0.0331, "
                       "w_res/w_max = 1.02 [1 - ((w* + 5.9)/6.9)^-0.54]; e = 1 for v <= V_c",
           .validity = "Etsion fit 1 <= w*_max <= 110 (extrapolated beyond; e = 0 where w_res > "
                       "w_max, w*_max > ~1e4)",
           .status = Status::kUnverified,
           .status_note = "structure one source (Ma et al. 2023); Etsion 2005 residual constants "
                          "UNCONFIRMED (recollection, not read in a public text; the normalised "
                          "JCG-2005 form is used so that w_res = 0 at w* = 1)",
           .clamped_by_default = true},
       [](const ImpactPair& pair, bool clamp, const FactoryContext& ctx) -> Model::Kernel {
         return JacksonGreen2010{.pair = pair,
                                 .residual = JacksonGreenResidual::kEtsion2005,
                                 .radius = ctx.options.radius,
                                 .clamp = clamp};
       }});
  r.push_back(
      {ModelInfo{.name = "jg2",
                 .title = "Jackson-Green-Marghitu 2010 J-G2 (continuous contact radius)",
                 .citation = kJgCitation,
                 .equation = "e^2 = W_unload/W_load, W_load = int_0^w_max P_JG2005 dw = m v^2/2, "
                             "Hertz unloading with R_bar = 4E* a_m^3/(3P_max): "
                             "W_unload = 3 P_max^2/(10 E* a_m); e = 1 for v <= V_c",
                 .validity = "JG 2005 FE fit w* <= ~110 (extrapolated beyond); Hertz (e = 1) for "
                             "w* <= 1.9, small jump (~1e-3) at w* = 1.9 from the loading law",
                 .status = Status::kVerifiedSecondSource,
                 .status_note =
                     "loading law confirmed (two sources); residual law confirmed (one source + "
                     "derivation); that JGM 2010's J-G2 uses exactly this residual law is "
                     "unconfirmed",
                 .clamped_by_default = true},
       [](const ImpactPair& pair, bool clamp, const FactoryContext& ctx) -> Model::Kernel {
         return JacksonGreen2010{.pair = pair,
                                 .residual = JacksonGreenResidual::kContinuousContactRadius,
                                 .radius = ctx.options.radius,
                                 .clamp = clamp};
       }});
  r.push_back(
      {ModelInfo{.name = "jg2010-fit",
                 .title = "Jackson-Green-Marghitu 2010 empirical fit, eps = S_y/E*",
                 .citation = kJgCitation,
                 .equation = std::string(kJgFitEquation) + "; eps = S_y/E*",
                 .validity = "fit to the JGM 2010 energy model; continuous at V' = 1",
                 .status = Status::kUnverified,
                 .status_note = "one source; the definition of eps is unconfirmed (S_y/E* here)",
                 .clamped_by_default = true},
       [](const ImpactPair& pair, bool clamp, const FactoryContext&) -> Model::Kernel {
         return JacksonGreen2010Fit{
             .pair = pair, .strain = JacksonGreenFitStrain::kYieldOverModulus, .clamp = clamp};
       }});
  r.push_back({ModelInfo{.name = "jg2010-fit-c",
                         .title = "Jackson-Green-Marghitu 2010 empirical fit, eps = C S_y/E*",
                         .citation = kJgCitation,
                         .equation = std::string(kJgFitEquation) + "; eps = C(nu) S_y/E*",
                         .validity = "fit to the JGM 2010 energy model; continuous at V' = 1",
                         .status = Status::kUnverified,
                         .status_note =
                             "one source; the definition of eps is unconfirmed (C(nu) S_y/E* here)",
                         .clamped_by_default = true},
               [](const ImpactPair& pair, bool clamp, const FactoryContext&) -> Model::Kernel {
                 return JacksonGreen2010Fit{
                     .pair = pair,
                     .strain = JacksonGreenFitStrain::kCTimesYieldOverModulus,
                     .clamp = clamp};
               }});
}

void add_wu2003_johnson1985(std::vector<Registration>& r) {
  r.push_back(
      {ModelInfo{
           .name = "wu2003",
           .title = "Wu, Li & Thornton 2003 (UNVERIFIED candidate form B)",
           .citation = "Wu C.-Y., Li L.-Y., Thornton C. (2003) Int. J. Impact Eng. 28(9):929-946 "
                       "(equation not read; candidate form B of the corlab model reference)",
           .equation = "e = 0.62 [(p_y/E*)(v/V_y)]^(-1/4) for v > V_y, p_y = 1.6 sigma_y, "
                       "V_y = 1.5605 sqrt(p_y^5/(E*^4 rho)); e = 1 below; NOT clamped by default",
           .validity = "unknown; exceeds 1 at low speed (as the seed paper reports for Wu's model)",
           .status = Status::kUnverified,
           .status_note =
               "unconfirmed: no text, abstract or implementation of the paper found; form "
               "B and its V_y definition are candidates only. Do not treat as exact",
           .clamped_by_default = false},
       [](const ImpactPair& pair, bool clamp, const FactoryContext&) -> Model::Kernel {
         return Wu2003{.pair = pair, .clamp = clamp};
       }});
  r.push_back(
      {ModelInfo{
           .name = "johnson1985",
           .title = "Johnson 1985 fully plastic rebound (p_d = 3Y)",
           .citation = "Johnson K.L. (1985) Contact Mechanics, Cambridge University Press, ch. 11",
           .equation = "e = sqrt(3.548) (2pi/3)^(-1/8) (p_d/E*)^(1/2) (rho v^2/p_d)^(-1/8), "
                       "p_d = 3Y, for v > V_Y = sqrt(26 Y^5/(rho E*^4)); e = 1 below; clamped at 1",
           .validity = "fully plastic impacts only (v >> V_Y); the raw formula exceeds 1 for "
                       "v <~ 1-2 m/s on the seed pairs, hence the default clamp",
           .status = Status::kVerifiedSecondSource,
           .status_note =
               "fully plastic rebound confirmed (one source + derivation); V_Y expression "
               "confirmed (two sources, via Thornton) but the printed constant 26 and "
               "Johnson's equation numbers are unconfirmed",
           .clamped_by_default = true},
       [](const ImpactPair& pair, bool clamp, const FactoryContext&) -> Model::Kernel {
         return Johnson1985{.pair = pair, .clamp = clamp};
       }});
}

void add_corlab2026(std::vector<Registration>& r) {
  r.push_back(
      {ModelInfo{
           .name = "corlab2026",
           .title = "corlab 2026: Thornton with the cavity-model contact pressure, fitted to "
                    "corlab's FE dataset",
           .citation = "corlab project, docs/theory/corlab_model.md; fitted to the FE restitution "
                       "dataset data/fe_restitution (coefficients: model_fit.json)",
           .equation =
               "e = T(x_w, phi_w) T(x_o*, phi_o)^w_o / (1 + b (D_y (x^2 - 1)/g)^c), x = v/v_y "
               "(first yield of the pair), T = e_Thornton(phi^2.5/x), phi = min(1 + c ln x + A "
               "(x^0.4 - 1), P g), c = c1 C(0.3)/C(nu_w), A = (1 - c/0.4) kappa_c h/(1 + kappa_c "
               "h), P = phi_max C(0.3)/C(nu_w) (times Jackson-Green's J(a/R) for a sphere that "
               "yields first), g = (1 + kappa h x^0.4)/(1 + kappa h), h = H/E*, x_w = 1 + "
               "exp(q_w (l_w - 1/2)) (x - 1), x_o* = phi_w^2.5 v/v_y,o / x, w_o = gamma exp(q_o "
               "(l_o - l_w)), l = E* (1 - nu^2)/E of a body; e = 1 for v <= v_y",
           .validity = "the dataset's box: sigma_y/E* 1e-3-1.5e-2, v from 1.1 v_y to 100 m/s and "
                       "rho v^2/sigma_y <= 0.26, E_sphere/E_substrate 0.2-5, nu 0.2-0.45, elastic "
                       "or yielding sphere (sigma_y ratio 0.5-5), H/E 0-0.05, equal densities",
           .status = Status::kVerifiedDataset,
           .status_note = "fitted by this project to its own FE dataset; held-out errors in "
                          "data/fe_restitution/model_fit.json and the README. The form is "
                          "derived from Thornton 1997, Johnson 1985 (cavity model, damage "
                          "number) and Tabor's representative strain",
           .clamped_by_default = true},
       [](const ImpactPair&, bool, const FactoryContext& ctx) -> Model::Kernel {
         return Corlab2026{.pair = corlab2026_pair(ctx.sphere, ctx.substrate),
                           .coefficients = corlab2026_fitted()};
       }});
}

void add_corlab2026p(std::vector<Registration>& r) {
  r.push_back(
      {ModelInfo{
           .name = "corlab2026p",
           .title = "corlab 2026 for particle pairs: corlab2026's form over a flat or a free "
                    "second sphere of any density, fitted to both FE datasets",
           .citation = "corlab project, docs/theory/corlab_model.md (Particle pairs); fitted to "
                       "data/fe_restitution and data/fe_restitution_pairs (coefficients: "
                       "data/fe_restitution_pairs/model_fit.json)",
           .equation =
               "corlab2026's e(v) with v_y and v_y,o at the pair's rho* = 3 m*/(4 pi R*^3), "
               "the damage number D_y = rho_w v_y^2/p_y on the density of the body w "
               "that yields first, and Jackson-Green's cap of a curved body w at a/R_w = "
               "(a/R*)(R*/R_w); radius_ratio = R1/R2 (0: a flat)",
           .validity = "the pair dataset's box: E_sphere/E_other 0.05-20, rho_sphere/rho_other "
                       "0.1-10, R1/R2 0-1, sigma_y/E* 1e-3-1.5e-2, v from 1.1 v_y to 100 m/s and "
                       "rho* v^2/sigma_y <= 0.26, nu 0.2-0.45, H/E 0-0.05",
           .status = Status::kVerifiedDataset,
           .status_note =
               "fitted by this project to its own FE datasets; held-out errors in "
               "data/fe_restitution_pairs/model_fit.json and the README (random 20 % "
               "and the corners E ratio > 10, density ratio > 5 held out): RMS <= 2 %, "
               "worst -10 %, up to a damage number rho* v^2/sigma_y of 0.003; beyond it, "
               "worst -15 % (random 20 %) and +46 % (density ratio > 5)",
           .clamped_by_default = true,
           .accurate_damage_number = kCorlab2026pAccurateDamageNumber,
           .fitted_radius_ratio = 1.0},
       [](const ImpactPair&, bool, const FactoryContext& ctx) -> Model::Kernel {
         return corlab2026p(ctx.impactor, ctx.substrate, ctx.options.radius_ratio);
       }});
}

/// The registry: one entry per model, in catalog order. Adding a model is one entry here.
const std::vector<Registration>& registry() {
  static const std::vector<Registration> entries = [] {
    std::vector<Registration> r;
    add_ma2023(r);
    add_thornton1997(r);
    add_jackson_green2010(r);
    add_wu2003_johnson1985(r);
    add_corlab2026(r);
    add_corlab2026p(r);
    return r;
  }();
  return entries;
}

std::size_t index_of(std::string_view name) {
  const auto& catalog = model_catalog();
  for (std::size_t i = 0; i < catalog.size(); ++i) {
    if (catalog[i].name == name) return i;
  }
  throw_invalid("model", name, fmt::format("one of [{}]", fmt::join(model_names(), ", ")));
}

}  // namespace

const std::vector<ModelInfo>& model_catalog() {
  static const std::vector<ModelInfo> catalog = [] {
    std::vector<ModelInfo> infos;
    for (const auto& entry : registry()) infos.push_back(entry.info);
    return infos;
  }();
  return catalog;
}

std::vector<std::string> model_names() {
  std::vector<std::string> names;
  for (const auto& info : model_catalog()) names.push_back(info.name);
  return names;
}

const ModelInfo& model_info(std::string_view name) { return model_catalog()[index_of(name)]; }

Model::Model(const ModelInfo& info, Kernel kernel, bool clamped)
    : info_(&info), kernel_(kernel), clamped_(clamped) {}

double Model::yield_velocity() const {
  return std::visit([](const auto& k) { return k.yield_velocity(); }, kernel_);
}

double Model::cor(double velocity) const {
  require_velocity(velocity);
  return std::visit([velocity](const auto& k) { return k.cor(velocity); }, kernel_);
}

void Model::cor(std::span<const double> velocities, std::span<double> out) const {
  if (out.size() != velocities.size()) {
    throw_invalid("output size", static_cast<double>(out.size()),
                  fmt::format("equal to the number of velocities ({})", velocities.size()));
  }
  require_velocities(velocities);
  std::visit(
      [&](const auto& k) {
        for (std::size_t i = 0; i < velocities.size(); ++i) out[i] = k.cor(velocities[i]);
      },
      kernel_);
}

std::vector<double> Model::cor(std::span<const double> velocities) const {
  std::vector<double> out(velocities.size());
  cor(velocities, out);
  return out;
}

Model make_model(std::string_view name,
                 const Material& sphere,
                 const Material& substrate,
                 const ModelOptions& options) {
  const ModelInfo& info = model_info(name);
  // e does not depend on R; a radius of 1e-300 or 1e300 m gave e = 0 (jg2) in round-off.
  if (!(options.radius >= kMinModelRadius && options.radius <= kMaxModelRadius)) {
    throw_invalid("radius", options.radius,
                  fmt::format("in [{:g}, {:g}] [m] (a nanometre to a kilometre)", kMinModelRadius,
                              kMaxModelRadius));
  }
  make_impact_pair(sphere, substrate, info.name);  // validates both materials first
  // The pair's Hertz impact: a sphere of density rho* on a flat.
  const Material reduced = pair_reduced_sphere(sphere, substrate, options.radius_ratio);
  const ImpactPair pair = make_impact_pair(reduced, substrate, info.name);
  const bool clamp = options.clamp.value_or(info.clamped_by_default);
  const FactoryContext ctx{options, reduced, substrate, sphere};
  return {info, registry()[index_of(name)].factory(pair, clamp, ctx), clamp};
}

}  // namespace corlab::restitution
