#pragma once
// What seed 002's two Euler-angle tracking laws share (PPATC, control/ppc_neural.hpp, and the
// ATC comparison law, control/adaptive_tracking.hpp; spec §B.3):
//   - input and gain types and the paper's Table 2 values,
//   - the kinematic step: ϑ̇ = F ω, e, ė, and ϑ̈ = A + B u + D̄ in closed form (steps 1, 10),
//   - the neural compensation and adaptation with the final u = B⁻¹(…) (steps 11-14).
// Each law supplies its sliding variable s and its model part of the bracket.
#include <cmath>
#include <limits>

#include "adcs/adapt/ppc.hpp"
#include "adcs/adapt/rbf_compensator.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/euler_dynamics.hpp"

namespace adcs {

//! Angle unit of the law's internal quantities (spec B.4 #18). The RBF input is in degrees in both.
enum class AngleUnits {
  radians,  //!< U_rad (default): SI radians — the only convention reproducing all of [002]'s claims
  degrees,  //!< U_deg: e, ė, ρ, A, ϑ̈_d in degrees; −Ks, D̂, μ̂ weigh 57.3x less
};

inline constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;
//! The same in the scalar S, rounded once from the double value.
template <class S>
inline constexpr S deg_per_rad_v = static_cast<S>(kDegPerRad);

//! RBF layer of seed 002 §4 / spec §B.5: 7 nodes on a 6-D input [e (deg); ė (deg/s)], widths 0.1.
//! Row 6, entry 1 repaired to −0.03 (spec B.4 #19). In the scalar S, each value rounded once at
//! compile time (a float flight build computes no double to set its defaults).
template <class S = double>
inline RbfLayerParams<6, 7, S> seed002_rbf_layer() noexcept {
  static constexpr S kCenters[6][7] = {
      {S(-0.25), S(-0.17), S(-0.08), S(0.0), S(0.08), S(0.17), S(0.25)},
      {S(-0.15), S(-0.10), S(-0.05), S(0.0), S(0.05), S(0.10), S(0.15)},
      {S(-0.20), S(-0.13), S(-0.07), S(0.0), S(0.07), S(0.13), S(0.20)},
      {S(-0.03), S(-0.02), S(-0.01), S(0.0), S(0.01), S(0.02), S(0.03)},
      {S(-0.15), S(-0.10), S(-0.05), S(0.0), S(0.05), S(0.10), S(0.15)},
      {S(-0.03), S(-0.02), S(-0.01), S(0.0), S(0.01), S(0.02), S(0.03)}};
  RbfLayerParams<6, 7, S> p;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 7; ++j) p.centers(i, j) = kCenters[i][j];
  p.widths.setConstant(S(0.1));
  return p;
}

//! Performance functions of seed 002 Table 2 in radians: ρ0 = 0.3°, ρ∞ = 0.005°, k = 0.15 1/s,
//! δ = 0 on every axis (admissible because no e_i(0) is zero, spec B.4 #15).
template <class S = double>
inline PpcParams<3, S> seed002_performance() noexcept {
  constexpr S rho0 = static_cast<S>(0.3 / kDegPerRad), rho_inf = static_cast<S>(0.005 / kDegPerRad);
  PpcParams<3, S> p;
  for (auto& f : p.rho) f = PerformanceFunctionT<S>{rho0, rho_inf, S(0.15)};
  p.delta.setZero();
  return p;
}

//! RBF compensator of seed 002 Table 2: τ_wi = τ_μ = 0.5, β = γ = 0.01, σ = 0.01.
template <class S = double>
inline RbfCompensatorParams<6, 7, 3, S> seed002_compensator() noexcept {
  RbfCompensatorParams<6, 7, 3, S> p;
  p.layer = seed002_rbf_layer<S>();
  p.tau_w.setConstant(S(0.5));
  p.tau_mu = S(0.5);
  p.beta = S(0.01);
  p.gamma = S(0.01);
  p.sigma = S(0.01);
  return p;
}

//! Gains shared by both laws (seed 002 Table 2 defaults).
template <class S = double>
struct EulerTrackingGainsT {
  //! [kg m²] inertia in B⁻¹ = J G and A (the paper uses the true J). No default: NaN until set,
  //! so a forgotten inertia is refused (status() == invalid_parameter), never taken as I.
  Mat<3, 3, S> J = Mat<3, 3, S>::Constant(unset_v<S>);
  Vec<3, S> lambda = Vec<3, S>::Constant(S(0.125));  //!< [1/s] λ, seed 002 Table 2
  Vec<3, S> K = Vec<3, S>(S(0.5), S(0.1), S(0.5));   //!< [law units] K, seed 002 Table 2
  RbfCompensatorParams<6, 7, 3, S> compensator = seed002_compensator<S>();  //!< τ_w, τ_μ, β, γ, σ, RBF layer
  AngleUnits units = AngleUnits::radians;    //!< spec B.4 #18
  S period_s = S(1.0e-4);                    //!< [s] spec §B.5 (the paper's law is continuous)
  FailurePolicy on_failure = FailurePolicy::safe_command;  //!< after a failed step: zero torque, or hold
  //! The same gains in another scalar (each value rounded once; validated by the law).
  template <class T>
  EulerTrackingGainsT<T> cast() const noexcept {
    EulerTrackingGainsT<T> q;
    q.J = scalar_cast<T>(J);
    q.lambda = scalar_cast<T>(lambda);
    q.K = scalar_cast<T>(K);
    q.compensator = compensator.template cast<T>();
    q.units = units;
    q.period_s = narrow_scalar<T>(period_s);
    q.on_failure = on_failure;
    return q;
  }
};
using EulerTrackingGains = EulerTrackingGainsT<double>;

//! What both Euler-angle laws read: the time since the manoeuvre started (ρ(t) of the PPC law
//! is measured from it), the attitude in its Euler view and the reference in the same view.
template <class S = double>
struct EulerTrackingInputT {
  S t_s = S(0);                          //!< [s] time since the start of the manoeuvre
  AttitudeStateEuler123T<S> state{};     //!< ϑ (x-y-z Euler angles of B relative to N), ω_BN_B
  EulerReferenceSampleT<S> reference{};  //!< ϑ_d, ϑ̇_d, ϑ̈_d
  template <class T>
  EulerTrackingInputT<T> cast() const noexcept {
    return {narrow_scalar<T>(t_s), state.template cast<T>(), reference.template cast<T>()};
  }
};
using EulerTrackingInput = EulerTrackingInputT<double>;

//! The shared arithmetic; owns the compensator, the last command and the validated constants.
template <class S = double>
class EulerTrackingCoreT {
 public:
  using Vec3S = Vec<3, S>;
  using Mat3S = Mat<3, 3, S>;
  using Torque = BodyTorqueT<S>;
  struct Kinematics {
    EulerAffineT<S> affine{};        //!< F, G, ϑ̇, A, B, B⁻¹ at the measurement
    Vec3S e = Vec3S::Zero();         //!< [rad] ϑ − ϑ_d
    Vec3S e_dot = Vec3S::Zero();     //!< [rad/s] ϑ̇ − ϑ̇_d
  };
  struct Compensation {
    Vec3S D_hat = Vec3S::Zero(), robust = Vec3S::Zero();
  };

  explicit EulerTrackingCoreT(const EulerTrackingGainsT<S>& g) noexcept : g_(g), comp_(g.compensator) {
    const Eigen::LLT<Mat3S> llt(g_.J);
    J_inv_ = llt.solve(Mat3S::Identity());
    const bool ok = all_finite(g_.J) && llt.info() == Eigen::Success && all_finite(J_inv_) &&
                    all_finite(g_.lambda) && (g_.lambda.array() > S(0)).all() && all_finite(g_.K) &&
                    (g_.K.array() > S(0)).all() && comp_.status() == Status::ok &&
                    std::isfinite(g_.period_s) && g_.period_s > S(0);
    status_ = ok ? Status::ok : Status::invalid_parameter;
  }
  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return g_.period_s; }
  S angle_scale() const noexcept { return g_.units == AngleUnits::degrees ? deg_per_rad_v<S> : S(1); }

  void reset() noexcept {
    comp_.reset();
    last_ = Torque{};
  }
  const Torque& last() const noexcept { return last_; }
  //! What a step outputs until it succeeds: zero torque, or the last good command (hold_last).
  Torque failure_command() const noexcept {
    return adcs::failure_command(g_.on_failure, last_, Torque{});
  }
  RbfCompensator<6, 7, 3, S>& compensator() noexcept { return comp_; }
  const RbfCompensator<6, 7, 3, S>& compensator() const noexcept { return comp_; }

  //! Steps 1 and 10: finite checks, ϑ̇ = F ω, e, ė, A, B⁻¹. non_finite_input or singular.
  [[nodiscard]] Status kinematics(const EulerTrackingInputT<S>& in, Kinematics& k) const noexcept {
    const AttitudeStateEuler123T<S>& m = in.state;
    const EulerReferenceSampleT<S>& r = in.reference;
    if (!std::isfinite(in.t_s) || !all_finite(r.angles) || !all_finite(r.angles_dot) ||
        !all_finite(r.angles_ddot))
      return Status::non_finite_input;
    const Status s = euler_affine<S>(g_.J, J_inv_, m.theta_BN_rad, m.omega_BN_B, k.affine);
    if (s != Status::ok) return s;
    k.e = m.theta_BN_rad - r.angles;
    k.e_dot = k.affine.angles_dot - r.angles_dot;
    return Status::ok;
  }

  //! Steps 11-14: u = B⁻¹ (law − D̂ − μ̂² s/(μ̂‖s‖ + σ) − K s) / c with `law` the model part in law
  //! units, then one period of seed 002 eqs. (13)-(14). Commits the estimates and the command only if
  //! everything is finite (out_of_range otherwise, nothing changed).
  [[nodiscard]] Status compensate_and_adapt(const Kinematics& k, const Vec3S& s, const Vec3S& law,
                                            Torque& out, Compensation& c) noexcept {
    if (!all_finite(s) || !all_finite(law)) return Status::out_of_range;
    Vec<6, S> x;
    x << deg_per_rad_v<S> * k.e, deg_per_rad_v<S> * k.e_dot;  // RBF input in degrees (spec B.4 #18)
    const auto o = comp_.evaluate(x, s);                                           // steps 11-12
    const Vec3S bracket = law - o.D_hat - o.robust - g_.K.cwiseProduct(s);
    const Vec3S u = k.affine.B_inv * (bracket / angle_scale());                    // step 13, seed 002 eq. (12)
    Mat<7, 3, S> W_next;
    S mu_next;
    comp_.propose(o, s, g_.period_s, W_next, mu_next);                     // step 14
    c.D_hat = o.D_hat;
    c.robust = o.robust;
    if (!all_finite(u) || !all_finite(W_next) || !std::isfinite(mu_next)) return Status::out_of_range;
    comp_.commit(W_next, mu_next);
    last_.torque_B_Nm = u;
    out = last_;
    return Status::ok;
  }

 private:
  EulerTrackingGainsT<S> g_;
  RbfCompensator<6, 7, 3, S> comp_;
  Mat3S J_inv_ = Mat3S::Identity();
  Torque last_{};
  Status status_ = Status::ok;
};
using EulerTrackingCore = EulerTrackingCoreT<double>;

}  // namespace adcs
