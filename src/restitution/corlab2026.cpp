// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/restitution/corlab2026.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string_view>
#include <utility>

#include "corlab/core/units.hpp"
#include "corlab/restitution/first_yield.hpp"
#include "corlab/restitution/jackson_green2005.hpp"
#include "corlab/restitution/thornton1997.hpp"
#include "restitution/fitted_coefficients.hpp"

namespace corlab::restitution {
namespace {

// phi^(5/2)/x decreases while d ln phi / d ln x < 2/5; the cavity branch keeps its rate below
// that bound for c1 up to this (the fit's bound).
constexpr double kMaxPressureSlope = 0.39;

// Flow stress over the yield stress for a hardening h = H / E* growing like the contact radius
// (Tabor's representative strain 0.2 a/R, a ~ x^(2/5)), 1 at first yield (x = 1); its rate in
// ln x stays below 2/5.
double flow_stress_ratio(double x, double h, double kappa) {
  return (1.0 + kappa * h * std::pow(x, 0.4)) / (1.0 + kappa * h);
}

// phi: the mean contact pressure over its value at first yield, for a body at x = v / v_y of that
// body, hardening h = H / E* and fully plastic cap phi_max (times a flattened sphere's factor).
double pressure_ratio(double x, double h, double cap, double c1, const Corlab2026Coefficients& k) {
  if (!(x > 1.0)) return 1.0;
  // Before the cap: the cavity model's c1 ln x plus hardening a (x^(2/5) - 1) with
  // a < 1 - c1/0.4, so that d ln phi / d ln x = (c1 + 0.4 a x^(2/5)) / phi < 2/5 for every x >= 1
  // (it holds at x = 1 and the margin grows with ln x).
  c1 = std::min(c1, kMaxPressureSlope);
  const double kh = k.kappa_cavity * h;
  const double a = (1.0 - c1 / 0.4) * kh / (1.0 + kh);
  const double cavity = 1.0 + c1 * std::log(x) + a * (std::pow(x, 0.4) - 1.0);
  return std::min(cavity, cap * flow_stress_ratio(x, h, k.kappa));
}

// Thornton's closed form with the limiting pressure phi p_y (v_y scales as p_y^(5/2)).
double thornton_factor(double x, double phi) {
  return x > 1.0 ? thornton_closed_form(std::pow(phi, 2.5) / x) : 1.0;
}

// The cavity model's slope and Tabor's hardness are in units of the yield stress; phi is in units
// of the first-yield pressure C(nu) Y: both scale as C(0.3) / C(nu) of the first body.
double poisson_scale(const Corlab2026Inputs& in) {
  return jackson_green_c(0.3) / jackson_green_c(in.poisson_first);
}

// R*/R_w of the body that yields first, its part of the pair's curvature 1/R* = 1/R1 + 1/R2
// (r = R1/R2): 1/(1 + r) for the sphere, r/(1 + r) for the other body (0 for a flat) [-].
double curvature_share_first(const Corlab2026Inputs& in) {
  const double r = in.radius_ratio;
  return (in.other_is_sphere ? r : 1.0) / (1.0 + r);
}

// The fully plastic cap of the body that yields first: Tabor's indentation hardness for a flat;
// for a curved body flattened by the other one, Jackson & Green's hardness, which falls as the
// flat grows (a/R_w from the first-yield contact radius a_y/R* growing like x^(2/5), times
// R*/R_w). Never below the first-yield pressure (phi = 1 at x = 1: e stays continuous for any
// input). poisson is poisson_scale(in).
double first_body_cap(const Corlab2026Inputs& in,
                      double x_first,
                      double poisson,
                      const Corlab2026Coefficients& k) {
  double cap = poisson * k.phi_max;
  const double share = curvature_share_first(in);
  if (share > 0.0) {
    const double a_over_r =
        k.flattening * in.contact_radius_at_yield * share * std::pow(x_first, 0.4);
    cap *= jackson_green_hardness_ratio(a_over_r) / jackson_green_hardness_ratio(0.0);
  }
  return std::max(1.0, cap);
}

// The fitted coefficients {name, value}: data/fe_restitution/model_fit.json's "coefficients",
// generated at configure time (cmake/Corlab2026Coefficients.cmake).
using detail::FittedValue;
constexpr auto kFitted = std::to_array<FittedValue>({
#include "corlab2026_fitted.inc"
});

constexpr int times_fitted(std::string_view name) {
  int n = 0;
  for (const auto& f : kFitted) n += f.name == name ? 1 : 0;
  return n;
}

constexpr bool listed(std::string_view name) {
  return std::any_of(kCorlab2026Coefficients.begin(), kCorlab2026Coefficients.end(),
                     [&](const auto& c) { return c.first == name; });
}

// A name as a template argument, so that a failed check names the coefficient (GCC: "In
// instantiation of ... [with Name<...> coefficient = Name<5>{"kappa"}]").
template <std::size_t N>
struct Name {
  std::array<char, N + 1> text{};  // 0-terminated: GCC prints it as a string
  constexpr explicit Name(std::string_view s) { std::copy_n(s.begin(), N, text.begin()); }
  constexpr std::string_view view() const { return {text.data(), N}; }
};

template <Name coefficient>
constexpr bool fitted_once() {
  static_assert(times_fitted(coefficient.view()) == 1,
                "a coefficient of kCorlab2026Coefficients (named above) is missing from "
                "data/fe_restitution/model_fit.json");
  return true;
}

template <Name coefficient>
constexpr bool in_the_list() {
  static_assert(listed(coefficient.view()),
                "data/fe_restitution/model_fit.json has a coefficient (named above) that "
                "kCorlab2026Coefficients lacks");
  return true;
}

template <std::size_t... I>
constexpr bool every_coefficient_fitted(std::index_sequence<I...> /*unused*/) {
  constexpr auto& list = kCorlab2026Coefficients;
  return (fitted_once<Name<list[I].first.size()>(list[I].first)>() && ...);
}

template <std::size_t... I>
constexpr bool every_fitted_value_listed(std::index_sequence<I...> /*unused*/) {
  return (in_the_list<Name<kFitted[I].name.size()>(kFitted[I].name)>() && ...);
}

static_assert(every_coefficient_fitted(std::make_index_sequence<kCorlab2026Coefficients.size()>{}));
static_assert(every_fitted_value_listed(std::make_index_sequence<kFitted.size()>{}));

}  // namespace

Corlab2026Coefficients corlab2026_fitted() {
  static constexpr Corlab2026Coefficients kCoefficients = detail::coefficients_from(kFitted);
  return kCoefficients;
}

Corlab2026Pair corlab2026_pair(const Material& sphere, const Material& substrate) {
  const FirstYield y = first_yield(sphere, substrate);
  const Material& first = y.sphere_first ? sphere : substrate;
  const Material& other = y.sphere_first ? substrate : sphere;
  const double e_star = effective_modulus(sphere, substrate);
  const double p_other = first_yield_pressure(other);
  return Corlab2026Pair{
      .yield_velocity = y.velocity,
      .yield_velocity_other = std::isfinite(p_other)
                                  ? thornton_yield_velocity(p_other, e_star, sphere.density)
                                  : std::numeric_limits<double>::infinity(),
      .inputs = {.hardening_first = first.hardening_modulus / e_star,
                 .hardening_other = other.yield_stress ? other.hardening_modulus / e_star : 0.0,
                 .damage_at_yield = sphere.density * y.velocity * y.velocity / y.pressure,
                 .compliance_share = (1.0 - sphere.poisson_ratio * sphere.poisson_ratio) /
                                     sphere.youngs_modulus * e_star,
                 .contact_radius_at_yield = units::kPi * y.pressure / (2.0 * e_star),
                 .poisson_first = first.poisson_ratio,
                 .other_is_sphere = !y.sphere_first}};
}

Corlab2026Inputs corlab2026_inputs(const Corlab2026Pair& pair, double velocity) {
  Corlab2026Inputs in = pair.inputs;
  in.velocity_ratio = velocity / pair.yield_velocity;
  in.velocity_ratio_other = velocity / pair.yield_velocity_other;
  return in;
}

Corlab2026Inputs corlab2026_inputs(const Material& sphere,
                                   const Material& substrate,
                                   double velocity) {
  return corlab2026_inputs(corlab2026_pair(sphere, substrate), velocity);
}

double corlab2026_restitution(const Corlab2026Inputs& in, const Corlab2026Coefficients& k) {
  const double x = in.velocity_ratio;
  if (!(x > 1.0)) return 1.0;
  // Compliance shares of the body that yields first and of the other one (they sum to 1).
  const double share_first = in.other_is_sphere ? 1.0 - in.compliance_share : in.compliance_share;
  const double share_other = 1.0 - share_first;
  // Plasticity grows faster beyond first yield in the body that takes more of the deformation:
  // its overload x - 1 is stretched (1 at first yield, Johnson's slope kept at high speed).
  const double x_first = 1.0 + std::exp(k.compliance_first * (share_first - 0.5)) * (x - 1.0);
  const double poisson = poisson_scale(in);
  const double phi_first = pressure_ratio(
      x_first, in.hardening_first, first_body_cap(in, x_first, poisson, k), k.c1 * poisson, k);
  // The other body feels the pressure the first one's plastic contact carries: its Hertz
  // overload is phi_first^(5/2) times the ratio of the two first-yield speeds.
  const double x_other = std::pow(phi_first, 2.5) * in.velocity_ratio_other / x;
  const double weight_other = (in.other_is_sphere ? k.gamma_sphere : k.gamma_substrate) *
                              std::exp(k.compliance_other * (share_other - share_first));
  // The damage number on the flow stress: hardening makes the crater shallower.
  const double damage =
      in.damage_at_yield * (x * x - 1.0) / flow_stress_ratio(x, in.hardening_first, k.kappa);
  const double crater = 1.0 + k.b * std::pow(damage, k.c);
  const double phi_other = pressure_ratio(x_other, in.hardening_other, k.phi_max, k.c1, k);
  return thornton_factor(x_first, phi_first) *
         std::pow(thornton_factor(x_other, phi_other), weight_other) / crater;
}

double Corlab2026::yield_velocity() const { return pair.yield_velocity; }

double Corlab2026::cor(double velocity) const {
  return corlab2026_restitution(corlab2026_inputs(pair, velocity), coefficients);
}

}  // namespace corlab::restitution
