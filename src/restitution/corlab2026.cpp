#include "corlab/restitution/corlab2026.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "corlab/restitution/first_yield.hpp"
#include "corlab/restitution/thornton1997.hpp"

namespace corlab::restitution {
namespace {

// phi^(5/2)/x decreases while d ln phi / d ln x < 2/5; the hardening exponent below keeps the
// rate under this bound (c1 <= it: the fit's bound).
constexpr double kMaxPressureSlope = 0.39;

// Flow stress at Tabor's representative strain over the yield stress, 1 at first yield (x = 1;
// its rate in ln x stays below 2/5).
double flow_stress_ratio(double x, double h, const Corlab2026Coefficients& k) {
  return (1.0 + k.kappa * h * std::pow(x, 0.4)) / (1.0 + k.kappa * h);
}

// Thornton's factor of one body at x = v / v_y of that body and its hardening h = H / E*.
double thornton_factor(double x, double h, const Corlab2026Coefficients& k) {
  if (!(x > 1.0)) return 1.0;
  const double hardening = flow_stress_ratio(x, h, k);
  // Before the cap the cavity-model growth (rate <= c1) takes hardening at the power
  // 1 - c1/0.39 (rate < 0.4 (1 - c1/0.39)): the sum stays below 2/5.
  const double c1 = std::min(k.c1, kMaxPressureSlope);
  const double phi =
      std::min((1.0 + c1 * std::log(x)) * std::pow(hardening, 1.0 - c1 / kMaxPressureSlope),
               k.phi_max * hardening);
  return thornton_closed_form(std::pow(phi, 2.5) / x);
}

}  // namespace

Corlab2026Coefficients corlab2026_fitted() {
  // data/fe_restitution/model_fit.json, "coefficients" (python/corlab/model_fit.py).
  return Corlab2026Coefficients{.c1 = 0.2530757238871905,
                                .phi_max = 2.811734766581207,
                                .kappa = 2.8129834990542295,
                                .b = 2.6542604115450823,
                                .c = 0.5824081661312523,
                                .gamma_sphere = 0.16144692526065815,
                                .gamma_substrate = 0.20584847966499523};
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
      .hardening_first = first.hardening_modulus / e_star,
      .hardening_other = other.yield_stress ? other.hardening_modulus / e_star : 0.0,
      .damage_at_yield = sphere.density * y.velocity * y.velocity / y.pressure,
      .other_is_sphere = !y.sphere_first};
}

Corlab2026Inputs corlab2026_inputs(const Corlab2026Pair& pair, double velocity) {
  return Corlab2026Inputs{.velocity_ratio = velocity / pair.yield_velocity,
                          .velocity_ratio_other = velocity / pair.yield_velocity_other,
                          .hardening_first = pair.hardening_first,
                          .hardening_other = pair.hardening_other,
                          .damage_at_yield = pair.damage_at_yield,
                          .other_is_sphere = pair.other_is_sphere};
}

Corlab2026Inputs corlab2026_inputs(const Material& sphere,
                                   const Material& substrate,
                                   double velocity) {
  return corlab2026_inputs(corlab2026_pair(sphere, substrate), velocity);
}

double corlab2026_restitution(const Corlab2026Inputs& in, const Corlab2026Coefficients& k) {
  const double x = in.velocity_ratio;
  if (!(x > 1.0)) return 1.0;
  const double gamma = in.other_is_sphere ? k.gamma_sphere : k.gamma_substrate;
  // The damage number on the flow stress: hardening makes the crater shallower.
  const double damage =
      in.damage_at_yield * (x * x - 1.0) / flow_stress_ratio(x, in.hardening_first, k);
  const double crater = 1.0 + k.b * std::pow(damage, k.c);
  return thornton_factor(x, in.hardening_first, k) *
         std::pow(thornton_factor(in.velocity_ratio_other, in.hardening_other, k), gamma) / crater;
}

double Corlab2026::yield_velocity() const { return pair.yield_velocity; }

double Corlab2026::cor(double velocity) const {
  return corlab2026_restitution(corlab2026_inputs(pair, velocity), coefficients);
}

}  // namespace corlab::restitution
