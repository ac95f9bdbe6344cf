#pragma once
// Pseudo-inverse steering for a 3×L actuator input matrix X (seed 001 §A.3 step 10): the
// minimum-norm u solving X u = v, u = Xᵀ(XXᵀ)⁻¹v through an LDLT of XXᵀ, with a
// singularity-robust fallback when the conditioning crosses a threshold: below σ_min =
// sigma_threshold the damped inverse Xᵀ(XXᵀ + λ²I)⁻¹v takes over, with λ² rising continuously
// from 0 (math/pinv.hpp), so the command never jumps at the switch and stays bounded at an
// exactly singular X. The status and SteeringInfo say which inverse produced u, the torque error
// it leaves and how close X is to singular; a command that misses its request by more than a
// documented bound is never reported usable (request_not_met). steer_escape() is the CMG law
// that leaves singular configurations instead of stalling there (Wie 2005, GSR inverse).
// Actuator failures: steer_available() solves over the available actuators only (a failed
// gimbal or wheel gets exactly 0 and the others take its share), the fallback FDIR applies.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Cholesky>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/pinv.hpp"

namespace adcs {

enum class SteeringMode : std::uint8_t {
  pseudo_inverse,      //!< exact minimum-norm solution, X u = v
  singularity_robust,  //!< damped least squares: X u ≈ v, |u| bounded
  singularity_escape,  //!< generalized singularity-robust inverse with dither (steer_escape)
};

//! What one steering call saw and delivered. The torque error is the fraction of the request the
//! command misses: e = ‖X u − v‖ / ‖v‖ (0 for v = 0), so 1 means "nothing of v is delivered".
//! S: the scalar of X (issue 19); steer_escape is double only.
template <class S = double>
struct SteeringInfoT {
  PinvInfoT<S> pinv;                            //!< singular values, condition, damping used
  SteeringMode mode = SteeringMode::pseudo_inverse;
  S singularity_measure = S(0);  //!< [-] m = √det(X̄ X̄ᵀ), X̄ = X / (largest column norm of X); 0 when singular
  S torque_error = S(0);         //!< [-] ‖X u − v‖ / ‖v‖ of the command written
  S regularization = S(0);       //!< [-] λ of steer_escape (on X̄ X̄ᵀ); pinv.damping for steer()
};
using SteeringInfo = SteeringInfoT<double>;

//! Smallest λ0 steer_escape accepts (on X̄X̄ᵀ, whose eigenvalues are O(1)). At a singular X̄,
//! λ = λ0 is all that keeps X̄X̄ᵀ + λE invertible; with λ0 ≥ 1e-8 and ε0 < 0.5 its smallest
//! eigenvalue stays far above rounding (eps ‖X̄X̄ᵀ‖ ~ 1e-15), so the Cholesky solve returns the
//! bounded command and not rounding noise.
inline constexpr double kEscapeLambda0Min = 1e-8;

//! Torque error up to which a regularised command is reported ok rather than ill_conditioned by
//! steer_escape (its λ never vanishes, so it is never exact): 0.1 % of the request.
inline constexpr double kSteeringOkTorqueError = 1e-3;

//! The damped fallback (sigma_threshold, lambda_max: math/pinv.hpp, in the units of X's singular
//! values, i.e. absolute) and the torque-error bound of a usable command. seed 001 A-REF sees
//! σ_min(X) ≈ 0.017 (spec §A.6 R9); the default 1e-3 leaves the paper's run on the exact inverse.
//! For a cluster of another size scale the thresholds with it, or use steer_escape, whose
//! thresholds are relative to the cluster's own scale.
template <class S = double>
struct SteeringParamsT {
  S sigma_threshold = S(1e-3);  //!< [X's units] σ_min below which damping starts
  S lambda_max = S(1e-2);       //!< [X's units] damping at σ_min = 0 (λ, not squared)
  S max_torque_error = S(0.1);  //!< [-] bound on ‖Xu − v‖/‖v‖ of a usable command, in (0, 1]
  template <class T>
  SteeringParamsT<T> cast() const noexcept {
    return {narrow_scalar<T>(sigma_threshold), narrow_scalar<T>(lambda_max), narrow_scalar<T>(max_torque_error)};
  }
};
using SteeringParams = SteeringParamsT<double>;

//! True when the steering parameters are finite and in range (thresholds ≥ 0, bound in (0, 1]).
template <class S>
inline bool valid(const SteeringParamsT<S>& p) noexcept {
  return std::isfinite(p.sigma_threshold) && p.sigma_threshold >= S(0) && std::isfinite(p.lambda_max) &&
         p.lambda_max >= S(0) && p.max_torque_error > S(0) && p.max_torque_error <= S(1);
}

namespace detail {
//! The singularity measure of X on its own scale: m = √det(X̄ X̄ᵀ), X̄ = X / max_k ‖x_k‖ (for a
//! CMG cluster, X̄'s columns are the unit torque axes of the largest rotors). 0 when X = 0.
//! Also returns the scale and X̄ X̄ᵀ for steer_escape.
template <int L, class S>
S singularity_measure(const Mat<3, L, S>& X, S& scale, Mat<3, 3, S>& G) noexcept {
  scale = X.colwise().norm().maxCoeff();
  if (!(scale > S(0))) {
    G.setZero();
    return S(0);
  }
  const Mat<3, L, S> Xn = X / scale;
  G.noalias() = Xn * Xn.transpose();
  return std::sqrt(std::max(G.determinant(), S(0)));
}

//! Fills the torque error of u and grades a command that was written: `within` (ok or the given
//! regularised status) while e ≤ bound, request_not_met beyond it. The caller fills the
//! singularity measure (steer_escape has it already).
template <int L, class S>
Status grade_command(const Mat<3, L, S>& X, const Vec<3, S>& v, const Vec<L, S>& u, S bound, Status within,
                     SteeringInfoT<S>& info) noexcept {
  const S v_norm = v.norm();
  const Vec<3, S> r = X * u - v;
  info.torque_error = v_norm > S(0) ? r.norm() / v_norm : (u.isZero(S(0)) ? S(0) : S(1));
  if (!(info.torque_error <= bound)) return Status::request_not_met;  // NaN included
  return within;
}
}  // namespace detail

//! u = X⁺v: the exact minimum-norm inverse while σ_min(X) ≥ sigma_threshold, the damped
//! (singularity-robust) inverse below it. Returns
//!  - ok: exact inverse (torque error at rounding level);
//!  - ill_conditioned: damped inverse, torque error ≤ max_torque_error: u usable;
//!  - request_not_met: damped inverse whose torque error exceeds max_torque_error (at a
//!    singularity with v along the lost direction the damped u is ~0 and delivers nothing):
//!    u is written, finite and bounded, but it is not what was asked; SteeringInfo says how much
//!    is missing. A controller treats it as a failed step (its safe command); steer_escape is
//!    the law that leaves such a configuration;
//!  - invalid_parameter, non_finite_input, singular or out_of_range (finite inputs whose solution
//!    overflows) with u untouched.
//! S is not deduced (X may be any Eigen expression): double unless given, `steer<L, float>(...)`.
template <int L, class S = double>
[[nodiscard]] Status steer(const identity_t<Mat<3, L, S>>& X, const identity_t<Vec<3, S>>& v,
                           const identity_t<SteeringParamsT<S>>& params, Vec<L, S>& u,
                           identity_t<SteeringInfoT<S>>* info = nullptr) noexcept {
  if (!valid(params)) return Status::invalid_parameter;
  SteeringInfoT<S> local;
  Vec<L, S> candidate;
  Status s = damped_right_pinv_solve<3, L, S>(X, v, candidate,
                                              DampingParamsT<S>{params.sigma_threshold, params.lambda_max}, &local.pinv);
  local.mode = local.pinv.damped ? SteeringMode::singularity_robust : SteeringMode::pseudo_inverse;
  local.regularization = local.pinv.damping;
  if (usable(s)) {
    S scale = S(0);
    Mat<3, 3, S> G;
    local.singularity_measure = detail::singularity_measure<L, S>(X, scale, G);
    s = detail::grade_command<L, S>(X, v, candidate, params.max_torque_error, s, local);
    u = candidate;
  }
  if (info) *info = local;
  return s;
}

//! The generalized singularity-robust (GSR) inverse of Wie (2005), "Singularity escape/avoidance
//! steering logic for control moment gyro systems", J. Guid. Control Dyn. 28(5):948-956:
//!
//!   u = X̄ᵀ (X̄ X̄ᵀ + λ E)⁻¹ v / s,   X̄ = X / s,  s = max_k ‖x_k‖ (the cluster's own scale)
//!   λ = λ0 exp(−μ m²),  m² = det(X̄ X̄ᵀ)
//!   E = [1 ε3 ε2; ε3 1 ε1; ε2 ε1 1],  εi = ε0 sin(ω t + φi)
//!
//! λ grows smoothly as the cluster nears a singular configuration, and the deterministic,
//! time-varying off-diagonal terms of E turn the part of v along the lost direction into torque
//! along the available ones, which moves the gimbals: the law passes through or leaves internal
//! singularities (elliptic ones included, which null motion alone cannot leave) at the price of
//! a transient torque error, instead of stalling there. Away from singularities λ is
//! ~λ0 e^(−μ m²) (≈ 1e-6 for a healthy four-CMG pyramid) and u is the pseudo-inverse's to that
//! order. Thresholds are relative: X̄ has unit-scale columns whatever the rotor momentum.
struct EscapeSteeringParams {
  double lambda0 = 0.01;                          //!< [-] λ at a singularity (Wie 2005: 0.01), ≥ kEscapeLambda0Min
  double mu = 10.0;                               //!< [-] decay of λ with det(X̄X̄ᵀ) (Wie 2005: 10), ≥ 0
  double epsilon0 = 0.01;                         //!< [-] dither amplitude (Wie 2005: 0.01), in [0, 0.5)
  double omega_rad_s = 0.5 * kPiRad;              //!< [rad/s] dither frequency (Wie 2005: π/2), ≥ 0
  Vec3 phase_rad = Vec3(0.0, 0.5 * kPiRad, kPiRad);  //!< [rad] φ1..φ3 (Wie 2005: 0, π/2, π)
  double max_torque_error = 0.1;                  //!< [-] bound on ‖Xu − v‖/‖v‖ of a usable command, in (0, 1]
};

//! Finite and in range; epsilon0 < 0.5 keeps E diagonally dominant (E ⪰ (1 − 2ε0) I), so
//! M = X̄X̄ᵀ + λE is positive definite for every X (λ > 0) and u is bounded:
//! ‖u‖² = v̄ᵀM⁻¹X̄X̄ᵀM⁻¹v̄ ≤ v̄ᵀM⁻¹v̄ ≤ ‖v̄‖² / (λ (1 − 2ε0)), v̄ = v / s, i.e.
//! ‖u‖ ≤ ‖v‖ / (s √(λ (1 − 2ε0))). (Without the dither, E = I, the tighter ‖v‖ / (2 s √λ)
//! holds; with it, E and X̄X̄ᵀ need not commute.)
inline bool valid(const EscapeSteeringParams& p) noexcept {
  return p.lambda0 >= kEscapeLambda0Min && std::isfinite(p.lambda0) && p.mu >= 0.0 && std::isfinite(p.mu) &&
         p.epsilon0 >= 0.0 && p.epsilon0 < 0.5 && p.omega_rad_s >= 0.0 && std::isfinite(p.omega_rad_s) &&
         all_finite(p.phase_rad) && p.max_torque_error > 0.0 && p.max_torque_error <= 1.0;
}

//! u = GSR inverse of X applied to v at time t_s [s] (the dither's phase: pass the sample time
//! k·T, so the command depends only on the inputs). Returns
//!  - ok: torque error ≤ kSteeringOkTorqueError; ill_conditioned: ≤ max_torque_error (usable);
//!  - request_not_met: the torque error exceeds max_torque_error (while escaping a singularity,
//!    or at the momentum envelope, where no law can deliver v): u is written, finite and bounded,
//!    and it is the escape command, meant to be applied; SteeringInfo reports the error;
//!  - invalid_parameter, non_finite_input, or out_of_range (finite inputs whose u overflows),
//!    with u untouched.
//! X = 0 (no authority at all) gives u = 0 and request_not_met for v ≠ 0.
template <int L>
[[nodiscard]] Status steer_escape(const Mat<3, L>& X, const Vec3& v, const EscapeSteeringParams& params,
                                  double t_s, Vec<L>& u, SteeringInfo* info = nullptr) noexcept {
  if (!valid(params)) return Status::invalid_parameter;
  if (!all_finite(X) || !all_finite(v) || !std::isfinite(t_s)) return Status::non_finite_input;
  SteeringInfo local;
  local.mode = SteeringMode::singularity_escape;
  double scale = 0.0;
  Mat3 G;
  const double m = detail::singularity_measure<L, double>(X, scale, G);
  Vec<L> candidate = Vec<L>::Zero();
  if (scale > 0.0) {
    const double lambda = params.lambda0 * std::exp(-params.mu * m * m);  // λ = λ0 exp(−μ det)
    Vec3 eps;
    for (int i = 0; i < 3; ++i) eps(i) = params.epsilon0 * std::sin(params.omega_rad_s * t_s + params.phase_rad(i));
    Mat3 E;
    E << 1.0, eps(2), eps(1),  //
        eps(2), 1.0, eps(0),   //
        eps(1), eps(0), 1.0;
    const Mat3 Mg = G + lambda * E;  // SPD: G ⪰ 0, λE ≻ 0
    const Eigen::LLT<Mat3> llt(Mg);
    if (llt.info() != Eigen::Success) return Status::out_of_range;  // only if λ underflowed
    const Vec3 y = llt.solve(v / scale);
    candidate.noalias() = (X / scale).transpose() * y;
    if (!all_finite(candidate)) return Status::out_of_range;
    local.regularization = lambda;
  }
  local.singularity_measure = m;
  const Status s =
      detail::grade_command<L, double>(X, v, candidate, params.max_torque_error, Status::ill_conditioned, local);
  const Status graded = (s == Status::ill_conditioned && local.torque_error <= kSteeringOkTorqueError) ? Status::ok : s;
  u = candidate;
  if (info) *info = local;
  return graded;
}

//! Bit k set = actuator k (column k of X) may be commanded. Fixed width: L ≤ 32.
using ActuatorMask = std::uint32_t;

//! Every actuator of an L-column X available.
template <int L>
constexpr ActuatorMask all_actuators() noexcept {
  static_assert(L >= 1 && L <= 32, "ActuatorMask holds at most 32 actuators");
  return L == 32 ? ~ActuatorMask{0} : (ActuatorMask{1} << L) - 1u;
}

//! u = X_a⁺v over the available actuators: X_a is X with the columns of unavailable actuators
//! zeroed, so the minimum-norm solution gives them exactly u_k = 0 (a zero column contributes
//! nothing to X_a X_aᵀ and u = X_aᵀ(·)⁻¹v) and spreads v over the rest. When the remaining
//! columns lose rank, the singularity-robust inverse takes over (ill_conditioned, u bounded;
//! request_not_met when what is left cannot deliver v within max_torque_error).
//! out_of_range (u untouched) when the mask names an actuator beyond L. The columns of
//! unavailable actuators are not read (a failed actuator's model may be garbage, NaN included).
template <int L, class S = double>
[[nodiscard]] Status steer_available(const identity_t<Mat<3, L, S>>& X, const identity_t<Vec<3, S>>& v,
                                     const identity_t<SteeringParamsT<S>>& params, ActuatorMask available,
                                     Vec<L, S>& u, identity_t<SteeringInfoT<S>>* info = nullptr) noexcept {
  if ((available & ~all_actuators<L>()) != 0u) return Status::out_of_range;
  if (available == all_actuators<L>()) return steer<L, S>(X, v, params, u, info);
  Mat<3, L, S> X_a = X;
  for (int k = 0; k < L; ++k)
    if (((available >> k) & 1u) == 0u) X_a.col(k).setZero();
  Vec<L, S> u_a;
  const Status s = steer<L, S>(X_a, v, params, u_a, info);
  if (!written(s)) return s;
  for (int k = 0; k < L; ++k)  // exact zeros, whatever the rounding of X_aᵀ y
    if (((available >> k) & 1u) == 0u) u_a(k) = S(0);
  u = u_a;
  return s;
}

}  // namespace adcs
