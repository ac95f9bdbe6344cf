#pragma once
// Per-actuator limits of a cluster of M gimbal motors and N wheels, declared once with the vehicle
// and applied to a command the way the hardware applies them (issue 15):
//   - each gimbal motor's rate |γ̇_i| ≤ γ̇_max,i;
//   - each wheel motor's torque |u_j| ≤ u_max,j (for a VSCMG command in wheel accelerations Ω̇_j,
//     |Ω̇_j| ≤ u_max,j / I_ws,j);
//   - each wheel's speed: at |Ω_j| ≥ Ω_max,j the wheel is not accelerated further outwards (its
//     command is held at zero in that direction; braking is always allowed).
// Element by element, like saturate_each (actuator/saturation.hpp): the direction of the body
// torque is not preserved. Where it matters, re-allocate over the wheels that are still free.
#include <cmath>
#include <limits>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

//! Defaults are +∞: "no limit" until you declare your hardware's (a documented configuration,
//! not a made-up number; a limit must be > 0, +∞ included).
template <int M, int N>
struct ActuatorLimits {
  Vec<M> gimbal_rate_max_rad_s = Vec<M>::Constant(std::numeric_limits<double>::infinity());  //!< [rad/s] per gimbal
  Vec<N> wheel_torque_max_Nm = Vec<N>::Constant(std::numeric_limits<double>::infinity());    //!< [N m] per wheel motor
  Vec<N> wheel_speed_max_rad_s = Vec<N>::Constant(std::numeric_limits<double>::infinity());  //!< [rad/s] per wheel
};

//! Every limit > 0 (+∞ allowed), none NaN.
template <int M, int N>
bool valid(const ActuatorLimits<M, N>& l) noexcept {
  auto positive = [](const auto& v) { return !v.hasNaN() && (v.array() > 0.0).all(); };
  return positive(l.gimbal_rate_max_rad_s) && positive(l.wheel_torque_max_Nm) && positive(l.wheel_speed_max_rad_s);
}

//! What a limiting call changed (0 everywhere: the command was within every limit).
struct LimitReport {
  int gimbal_rate_clipped = 0;  //!< gimbal rates clipped to their maximum
  int wheel_torque_clipped = 0;  //!< wheel torques (accelerations) clipped
  int wheel_speed_held = 0;      //!< wheels at their speed limit whose outward command was zeroed
  bool any() const noexcept { return gimbal_rate_clipped + wheel_torque_clipped + wheel_speed_held > 0; }
};

namespace detail {
//! Clamps x to [−max, max]; true if it had to.
inline bool clip(double& x, double max) noexcept {
  if (x > max) {
    x = max;
    return true;
  }
  if (x < -max) {
    x = -max;
    return true;
  }
  return false;
}

//! |x| ≤ max, then no outward command at the speed limit. Counts into `r`.
inline double limit_wheel(double x, double max, double Omega, double Omega_max, LimitReport& r) noexcept {
  if (clip(x, max)) ++r.wheel_torque_clipped;
  if (std::fabs(Omega) >= Omega_max && x != 0.0 && (x > 0.0) == (Omega > 0.0)) {
    x = 0.0;
    ++r.wheel_speed_held;
  }
  return x;
}
}  // namespace detail

//! Reaction-wheel motor torques u_s [N m] with the wheels at speeds Omega [rad/s] (relative to
//! the body). ok (within every limit) or saturated (clipped or held; `report` says which);
//! invalid_parameter or non_finite_input leave u_s untouched.
template <int N>
[[nodiscard]] Status limit_wheel_torques(const ActuatorLimits<0, N>& limits, const Vec<N>& Omega_rad_s, Vec<N>& u_s,
                                         LimitReport* report = nullptr) noexcept {
  if (!valid(limits)) return Status::invalid_parameter;
  if (!all_finite(Omega_rad_s) || !all_finite(u_s)) return Status::non_finite_input;
  LimitReport r;
  for (int j = 0; j < N; ++j)
    u_s(j) = detail::limit_wheel(u_s(j), limits.wheel_torque_max_Nm(j), Omega_rad_s(j), limits.wheel_speed_max_rad_s(j), r);
  if (report) *report = r;
  return r.any() ? Status::saturated : Status::ok;
}

//! A VSCMG command u = [γ̇ (M) [rad/s]; Ω̇ (N) [rad/s²]] with the wheels' spin inertias I_ws
//! [kg m²] (> 0; the torque limit becomes |Ω̇_j| ≤ u_max,j / I_ws,j) and speeds Omega [rad/s].
//! ok or saturated as above; invalid_parameter (also for I_ws not > 0) or non_finite_input leave
//! u untouched.
template <int M, int N>
[[nodiscard]] Status limit_vscmg_command(const ActuatorLimits<M, N>& limits, const Vec<N>& I_ws_kgm2,
                                         const Vec<N>& Omega_rad_s, Vec<M + N>& u,
                                         LimitReport* report = nullptr) noexcept {
  if (!valid(limits) || I_ws_kgm2.hasNaN() || !(I_ws_kgm2.array() > 0.0).all()) return Status::invalid_parameter;
  if (!all_finite(Omega_rad_s) || !all_finite(u)) return Status::non_finite_input;
  LimitReport r;
  for (int i = 0; i < M; ++i)
    if (detail::clip(u(i), limits.gimbal_rate_max_rad_s(i))) ++r.gimbal_rate_clipped;
  for (int j = 0; j < N; ++j)
    u(M + j) = detail::limit_wheel(u(M + j), limits.wheel_torque_max_Nm(j) / I_ws_kgm2(j), Omega_rad_s(j),
                                   limits.wheel_speed_max_rad_s(j), r);
  if (report) *report = r;
  return r.any() ? Status::saturated : Status::ok;
}

}  // namespace adcs
