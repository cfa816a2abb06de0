// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file separation_rule.hpp
/// The stop rule that defines e: contact bookkeeping (first and last step with a penetrating
/// slave) and the steady-rebound test. After the last contact the sphere's centre-of-mass
/// velocity is watched over windows of max(kWindowFractionOfContact x contact time, t_wave); the
/// run ends when it changes by less than kSteadyTolerance over one window (the elastic sphere
/// still rings, but its momentum no longer changes), and the rebound is clean only if the sphere
/// then moves away from the substrate. Re-contact restarts the watch. A run that needs e only
/// (SimulationControl::e_only: the error bar's companions) watches over shorter windows,
/// kEOnlyWindowFraction of the contact time and at least kEOnlyWaveFraction of t_wave (one wave
/// transit): after the last contact nothing acts on the sphere, so its c.o.m. velocity, and so
/// e, is already final; the window only has to catch a re-contact (and the chatter of the first
/// touch, which the floor spans).

namespace corlab::fem {

class SeparationRule {
 public:
  /// Window length as a fraction of the contact duration [-].
  static constexpr double kWindowFractionOfContact = 0.1;
  /// Steady when |v(window end) - v(window start)| < kSteadyTolerance x max(|v|, kVelocityFloor
  /// x v_impact) [-]: relative, with a floor so that a rebound near zero speed still ends.
  static constexpr double kSteadyTolerance = 1e-4;
  static constexpr double kVelocityFloor = 1e-3;
  /// Window as a fraction of the contact duration of a run that needs e only [-].
  static constexpr double kEOnlyWindowFraction = 0.02;
  /// Shortest window of a run that needs e only, as a fraction of t_wave [-].
  static constexpr double kEOnlyWaveFraction = 0.25;

  enum class Decision {
    kContinue,   ///< keep stepping
    kRebound,    ///< steady and moving away from the substrate: a clean rebound
    kNoRebound,  ///< steady without contact but not moving away (passed through / stuck)
  };

  /// t_wave [s]: shortest window (a few sphere wave transits); v_impact [m/s] > 0;
  /// window_fraction [-]: the window's part of the contact duration.
  SeparationRule(double t_wave, double v_impact, double window_fraction = kWindowFractionOfContact)
      : t_wave_(t_wave), v_impact_(v_impact), window_fraction_(window_fraction) {}

  /// The rule of a run that needs e only (SimulationControl::e_only): windows of
  /// kEOnlyWindowFraction of the contact duration, at least kEOnlyWaveFraction x t_wave [s].
  static SeparationRule e_only(double t_wave, double v_impact) {
    return {kEOnlyWaveFraction * t_wave, v_impact, kEOnlyWindowFraction};
  }

  /// Adds the sphere kinetic energy [J] over dt [s] to the window's time integral.
  void accumulate(double sphere_kinetic_energy, double dt) {
    if (separated_) window_ke_integral_ += sphere_kinetic_energy * dt;
  }

  /// One step ended at time t [s] (dt_prev [s]: its length); `penetrating`: any slave in
  /// contact; v_com [m/s]: sphere c.o.m. velocity, + away from the substrate.
  Decision update(double t, double dt_prev, bool penetrating, double v_com) {
    if (penetrating) {
      if (!touched_) t_first_ = t - dt_prev;
      touched_ = true;
      in_contact_ = true;
      t_last_ = t;
      separated_ = false;  // re-contact: the watch starts again
    } else if (in_contact_) {
      in_contact_ = false;
    }
    if (touched_ && !in_contact_ && !separated_) {
      separated_ = true;
      window_ = t_last_ - t_first_;
      window_ = window_fraction_ * window_ > t_wave_ ? window_fraction_ * window_ : t_wave_;
      start_window(t, v_com);
    } else if (separated_ && t - window_start_ >= window_) {
      const double change = v_com > window_v_ref_ ? v_com - window_v_ref_ : window_v_ref_ - v_com;
      const double speed = v_com < 0.0 ? -v_com : v_com;
      const double floor = kVelocityFloor * v_impact_;
      mean_sphere_ke_ = window_ke_integral_ / (t - window_start_);
      if (change < kSteadyTolerance * (speed > floor ? speed : floor)) {
        return v_com > 0.0 ? Decision::kRebound : Decision::kNoRebound;
      }
      start_window(t, v_com);
    }
    return Decision::kContinue;
  }

  bool touched() const { return touched_; }
  bool separated() const { return separated_; }
  /// Contact duration so far [s] (0 before the first contact).
  double contact_time() const { return touched_ ? t_last_ - t_first_ : 0.0; }
  /// Sphere kinetic energy averaged over the last complete window [J].
  double mean_sphere_kinetic_energy() const { return mean_sphere_ke_; }

 private:
  void start_window(double t, double v_com) {
    window_start_ = t;
    window_v_ref_ = v_com;
    window_ke_integral_ = 0.0;
  }

  double t_wave_;
  double v_impact_;
  double window_fraction_;
  bool touched_ = false;
  bool in_contact_ = false;
  bool separated_ = false;
  double t_first_ = 0.0;
  double t_last_ = 0.0;
  double window_ = 0.0;
  double window_start_ = 0.0;
  double window_v_ref_ = 0.0;
  double window_ke_integral_ = 0.0;
  double mean_sphere_ke_ = 0.0;
};

}  // namespace corlab::fem
