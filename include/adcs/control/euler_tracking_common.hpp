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

//! RBF layer of seed 002 §4 / spec §B.5: 7 nodes on a 6-D input [e (deg); ė (deg/s)], widths 0.1.
//! Row 6, entry 1 repaired to −0.03 (spec B.4 #19).
inline RbfLayerParams<6, 7> seed002_rbf_layer() noexcept {
  RbfLayerParams<6, 7> p;
  p.centers << -0.25, -0.17, -0.08, 0.0, 0.08, 0.17, 0.25,  //
      -0.15, -0.10, -0.05, 0.0, 0.05, 0.10, 0.15,           //
      -0.20, -0.13, -0.07, 0.0, 0.07, 0.13, 0.20,           //
      -0.03, -0.02, -0.01, 0.0, 0.01, 0.02, 0.03,           //
      -0.15, -0.10, -0.05, 0.0, 0.05, 0.10, 0.15,           //
      -0.03, -0.02, -0.01, 0.0, 0.01, 0.02, 0.03;
  p.widths.setConstant(0.1);
  return p;
}

//! Performance functions of seed 002 Table 2 in radians: ρ0 = 0.3°, ρ∞ = 0.005°, k = 0.15 1/s,
//! δ = 0 on every axis (admissible because no e_i(0) is zero, spec B.4 #15).
inline PpcParams<3> seed002_performance() noexcept {
  PpcParams<3> p;
  for (auto& f : p.rho) f = PerformanceFunction{0.3 / kDegPerRad, 0.005 / kDegPerRad, 0.15};
  p.delta.setZero();
  return p;
}

//! RBF compensator of seed 002 Table 2: τ_wi = τ_μ = 0.5, β = γ = 0.01, σ = 0.01.
inline RbfCompensatorParams<6, 7, 3> seed002_compensator() noexcept {
  RbfCompensatorParams<6, 7, 3> p;
  p.layer = seed002_rbf_layer();
  p.tau_w.setConstant(0.5);
  p.tau_mu = 0.5;
  p.beta = 0.01;
  p.gamma = 0.01;
  p.sigma = 0.01;
  return p;
}

//! Gains shared by both laws (seed 002 Table 2 defaults).
struct EulerTrackingGains {
  //! [kg m²] inertia in B⁻¹ = J G and A (the paper uses the true J). No default: NaN until set,
  //! so a forgotten inertia is refused (status() == invalid_parameter), never taken as I.
  Mat3 J = Mat3::Constant(kUnset);
  Vec3 lambda = Vec3::Constant(0.125);       //!< [1/s] λ, seed 002 Table 2
  Vec3 K = Vec3(0.5, 0.1, 0.5);              //!< [law units] K, seed 002 Table 2
  RbfCompensatorParams<6, 7, 3> compensator = seed002_compensator();  //!< τ_w, τ_μ, β, γ, σ, RBF layer
  AngleUnits units = AngleUnits::radians;    //!< spec B.4 #18
  double period_s = 1.0e-4;                  //!< [s] spec §B.5 (the paper's law is continuous)
  FailurePolicy on_failure = FailurePolicy::safe_command;  //!< after a failed step: zero torque, or hold
};

//! What both Euler-angle laws read: the time since the manoeuvre started (ρ(t) of the PPC law
//! is measured from it), the attitude in its Euler view and the reference in the same view.
struct EulerTrackingInput {
  double t_s = 0.0;                 //!< [s] time since the start of the manoeuvre
  AttitudeStateEuler123 state{};    //!< ϑ (x-y-z Euler angles of B relative to N), ω_BN_B
  EulerReferenceSample reference{};  //!< ϑ_d, ϑ̇_d, ϑ̈_d
};

//! The shared arithmetic; owns the compensator, the last command and the validated constants.
class EulerTrackingCore {
 public:
  struct Kinematics {
    EulerAffine affine{};          //!< F, G, ϑ̇, A, B, B⁻¹ at the measurement
    Vec3 e = Vec3::Zero();         //!< [rad] ϑ − ϑ_d
    Vec3 e_dot = Vec3::Zero();     //!< [rad/s] ϑ̇ − ϑ̇_d
  };
  struct Compensation {
    Vec3 D_hat = Vec3::Zero(), robust = Vec3::Zero();
  };

  explicit EulerTrackingCore(const EulerTrackingGains& g) noexcept : g_(g), comp_(g.compensator) {
    const Eigen::LLT<Mat3> llt(g_.J);
    J_inv_ = llt.solve(Mat3::Identity());
    const bool ok = all_finite(g_.J) && llt.info() == Eigen::Success && all_finite(J_inv_) &&
                    all_finite(g_.lambda) && (g_.lambda.array() > 0.0).all() && all_finite(g_.K) &&
                    (g_.K.array() > 0.0).all() && comp_.status() == Status::ok &&
                    std::isfinite(g_.period_s) && g_.period_s > 0.0;
    status_ = ok ? Status::ok : Status::invalid_parameter;
  }
  Status status() const noexcept { return status_; }
  double period_s() const noexcept { return g_.period_s; }
  double angle_scale() const noexcept { return g_.units == AngleUnits::degrees ? kDegPerRad : 1.0; }

  void reset() noexcept {
    comp_.reset();
    last_ = BodyTorque{};
  }
  const BodyTorque& last() const noexcept { return last_; }
  //! What a step outputs until it succeeds: zero torque, or the last good command (hold_last).
  BodyTorque failure_command() const noexcept {
    return adcs::failure_command(g_.on_failure, last_, BodyTorque{});
  }
  RbfCompensator<6, 7, 3>& compensator() noexcept { return comp_; }
  const RbfCompensator<6, 7, 3>& compensator() const noexcept { return comp_; }

  //! Steps 1 and 10: finite checks, ϑ̇ = F ω, e, ė, A, B⁻¹. non_finite_input or singular.
  [[nodiscard]] Status kinematics(const EulerTrackingInput& in, Kinematics& k) const noexcept {
    const AttitudeStateEuler123& m = in.state;
    const EulerReferenceSample& r = in.reference;
    if (!std::isfinite(in.t_s) || !all_finite(r.angles) || !all_finite(r.angles_dot) ||
        !all_finite(r.angles_ddot))
      return Status::non_finite_input;
    const Status s = euler_affine(g_.J, J_inv_, m.theta_BN_rad, m.omega_BN_B, k.affine);
    if (s != Status::ok) return s;
    k.e = m.theta_BN_rad - r.angles;
    k.e_dot = k.affine.angles_dot - r.angles_dot;
    return Status::ok;
  }

  //! Steps 11-14: u = B⁻¹ (law − D̂ − μ̂² s/(μ̂‖s‖ + σ) − K s) / c with `law` the model part in law
  //! units, then one period of seed 002 eqs. (13)-(14). Commits the estimates and the command only if
  //! everything is finite (out_of_range otherwise, nothing changed).
  [[nodiscard]] Status compensate_and_adapt(const Kinematics& k, const Vec3& s, const Vec3& law,
                                            BodyTorque& out, Compensation& c) noexcept {
    if (!all_finite(s) || !all_finite(law)) return Status::out_of_range;
    Vec<6> x;
    x << kDegPerRad * k.e, kDegPerRad * k.e_dot;  // RBF input in degrees (spec B.4 #18)
    const auto o = comp_.evaluate(x, s);                                           // steps 11-12
    const Vec3 bracket = law - o.D_hat - o.robust - g_.K.cwiseProduct(s);
    const Vec3 u = k.affine.B_inv * (bracket / angle_scale());                     // step 13, seed 002 eq. (12)
    Mat<7, 3> W_next;
    double mu_next;
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
  EulerTrackingGains g_;
  RbfCompensator<6, 7, 3> comp_;
  Mat3 J_inv_ = Mat3::Identity();
  BodyTorque last_{};
  Status status_ = Status::ok;
};

}  // namespace adcs
