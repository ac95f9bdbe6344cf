#pragma once
// Flexible spacecraft: rigid hub + P appendages (solar panels) with NM retained modes each,
// hybrid-coordinate model of seed 002 eqs. (1)-(3) (spec §B.2, repaired reading B.4 #1):
//
//   J ω̇ + ω × J ω + Σ_l ( F_sl η̈_l + ω × F_sl η̇_l ) = u + d                 seed 002 eq. (1)
//   η̈_l + 2 ξ_l Ω_l η̇_l + Ω_l² η_l + F_slᵀ ω̇ = 0                             seed 002 eq. (2)
//   ϑ̇ = F(ϑ) ω   (x-y-z Euler angles, math/euler.hpp)                        seed 002 eq. (3)
//
// integrated in the explicit form (spec §B.2), which needs M_eff = J − Σ_l F_sl F_slᵀ SPD:
//
//   ω̇  = M_eff⁻¹ [ u + d − ω × J ω − Σ_l ω × F_sl η̇_l + Σ_l F_sl (2 ξ_l Ω_l η̇_l + Ω_l² η_l) ]
//   η̈_l = −2 ξ_l Ω_l η̇_l − Ω_l² η_l − F_slᵀ ω̇
//
// and the Euler–Lagrange quantities of seed 002 eq. (4) for the controllers and the tests:
//
//   ϑ̈ = A + B u + D̄,  A = −F Ġ ϑ̇ − F J⁻¹ (ω × J ω),  B = F J⁻¹,  B⁻¹ = J G,
//   D̄ = F J⁻¹ [ d − Σ_l (F_sl η̈_l + ω × F_sl η̇_l) ],   J* = Gᵀ J G,  C = Gᵀ J Ġ − Gᵀ (J G ϑ̇)× G.
//
// Units: J [kg m²], F_sl [kg^½ m], η [kg^½ m], Ω [rad/s], ξ [-], u and d [N m], angles [rad].
#include <array>
#include <limits>

#include <Eigen/Cholesky>

#include "adcs/core/failure_hook.hpp"
#include "adcs/core/plant.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/euler.hpp"
#include "adcs/math/euler_dynamics.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

namespace detail {
//! P copies of a fixed-size Eigen object filled with kUnset ("no default: set it").
template <class T, int P>
std::array<T, P> unset_array() noexcept {
  std::array<T, P> a;
  for (auto& x : a) x.setConstant(kUnset);
  return a;
}
}  // namespace detail

//! Parameters of a hub with P appendages of NM modes each (seed 002 Table 1 for P = 2, NM = 4:
//! flexible_params_seed002()). No field has a default: NaN until set, so a forgotten one is
//! refused (an Eigen member of a std::array would otherwise be left uninitialised).
template <int P, int NM>
struct FlexibleSpacecraftParams {
  static_assert(P >= 1 && NM >= 1, "FlexibleSpacecraftParams: need P >= 1 panels, NM >= 1 modes");
  Mat3 J = Mat3::Constant(kUnset);  //!< [kg m²] total inertia incl. panels
  std::array<Mat<3, NM>, P> F_s = detail::unset_array<Mat<3, NM>, P>();  //!< [kg^½ m] rotation/mode coupling F_sl
  std::array<Vec<NM>, P> Omega = detail::unset_array<Vec<NM>, P>();      //!< [rad/s] natural frequencies (diag Ω_l)
  std::array<Vec<NM>, P> xi = detail::unset_array<Vec<NM>, P>();         //!< [-] modal damping ratios (diag ξ_l)
};

//! Truth plant of seed 002 (spec §B.2).
//!
//! State  x = [ϑ (3) [rad] x-y-z Euler angles of B relative to N; ω_BN_B (3) [rad/s];
//!             η_1 .. η_P (NM each) [kg^½ m]; η̇_1 .. η̇_P (NM each) [kg^½ m/s]]  (22 for 2 × 4).
//! Input  torque_B (3) [N m]: everything applied to the hub, u + d (the scenario adds d(t)).
template <int P, int NM>
class FlexibleSpacecraft {
 public:
  static constexpr int kPanels = P;
  static constexpr int kModes = NM;
  static constexpr int kModalSize = P * NM;
  static constexpr int kStateSize = 6 + 2 * kModalSize;
  static constexpr int kInputSize = 3;
  using State = Vec<kStateSize>;
  using Input = Vec3;
  using Params = FlexibleSpacecraftParams<P, NM>;

  //! Validates J (symmetric, SPD), M_eff SPD, Ω > 0, ξ >= 0; status() says the outcome.
  explicit FlexibleSpacecraft(const Params& p) noexcept : p_(p) {
    M_eff_ = p_.J;
    bool ok = all_finite(p_.J) && (p_.J - p_.J.transpose()).norm() <= 1e-12 * p_.J.norm();
    for (int l = 0; l < P; ++l) {
      ok = ok && all_finite(p_.F_s[l]) && all_finite(p_.Omega[l]) && all_finite(p_.xi[l]) &&
           (p_.Omega[l].array() > 0.0).all() && (p_.xi[l].array() >= 0.0).all();
      M_eff_ -= p_.F_s[l] * p_.F_s[l].transpose();
    }
    const Eigen::LLT<Mat3> llt_J(p_.J), llt_M(M_eff_);
    ok = ok && llt_J.info() == Eigen::Success && llt_M.info() == Eigen::Success;
    status_ = ADCS_CHECK(ok, "FlexibleSpacecraft: J and M_eff = J - sum F F^T must be SPD, "
                             "Omega > 0, xi >= 0, all finite")
                  ? Status::ok
                  : Status::invalid_parameter;
    J_inv_ = llt_J.solve(Mat3::Identity());
    M_eff_inv_ = llt_M.solve(Mat3::Identity());
  }

  //! ok, or invalid_parameter: J not finite, not symmetric or not positive definite; an F_sl
  //! not finite; M_eff = J − Σ F_sl F_slᵀ not positive definite; an Ω not finite > 0 or a ξ not
  //! finite >= 0. A refused plant has no dynamics: derivative() gives xdot = 0.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  const Mat3& M_eff() const noexcept { return M_eff_; }
  const Mat3& J_inv() const noexcept { return J_inv_; }

  static Vec3 angles(const State& x) noexcept { return x.template head<3>(); }
  static Vec3 omega_BN_B(const State& x) noexcept { return x.template segment<3>(3); }
  static Vec<NM> eta(const State& x, int l) noexcept { return x.template segment<NM>(6 + l * NM); }
  static Vec<NM> eta_dot(const State& x, int l) noexcept {
    return x.template segment<NM>(6 + kModalSize + l * NM);
  }

  //! x_dot = f(x, torque_B) by the explicit form above. At gimbal lock (|θ| → 90°) ϑ̇ is not
  //! defined: the derivative is NaN there and the integrator reports it (spec §B.2: |θ| < 89°).
  void derivative(double /*t*/, const State& x, const Input& torque_B, State& xdot) const noexcept {
    if (status_ != Status::ok) {  // no valid model: a finite, frozen state instead of NaN
      xdot.setZero();
      return;
    }
    const Vec3 w = omega_BN_B(x);
    Vec3 rhs = torque_B - w.cross(p_.J * w);
    for (int l = 0; l < P; ++l) {
      const Vec<NM> e = eta(x, l), ed = eta_dot(x, l);
      rhs += -w.cross(p_.F_s[l] * ed) +
             p_.F_s[l] * (2.0 * p_.xi[l].cwiseProduct(p_.Omega[l]).cwiseProduct(ed) +
                          p_.Omega[l].cwiseAbs2().cwiseProduct(e));
    }
    const Vec3 w_dot = M_eff_inv_ * rhs;
    Mat3 F;
    if (euler123_F(angles(x), F) != Status::ok) F.setConstant(std::numeric_limits<double>::quiet_NaN());
    xdot.template head<3>() = F * w;
    xdot.template segment<3>(3) = w_dot;
    for (int l = 0; l < P; ++l) {
      const Vec<NM> e = eta(x, l), ed = eta_dot(x, l);
      xdot.template segment<NM>(6 + l * NM) = ed;
      xdot.template segment<NM>(6 + kModalSize + l * NM) =
          -2.0 * p_.xi[l].cwiseProduct(p_.Omega[l]).cwiseProduct(ed) -
          p_.Omega[l].cwiseAbs2().cwiseProduct(e) - p_.F_s[l].transpose() * w_dot;  // seed 002 eq. (2)
    }
  }

  //! Lumped disturbance D̄ = F J⁻¹ [d − Σ_l (F_sl η̈_l + ω × F_sl η̇_l)] [rad/s²] at x, given the
  //! external torque d and the state derivative xdot = f(x, u + d) (for η̈). The truth the RBF
  //! network approximates (spec §B.2; oracle check B-S9). NaN at gimbal lock.
  Vec3 lumped_disturbance(const State& x, const Vec3& d, const State& xdot) const noexcept {
    const Vec3 w = omega_BN_B(x);
    Vec3 inner = d;
    for (int l = 0; l < P; ++l)
      inner -= p_.F_s[l] * xdot.template segment<NM>(6 + kModalSize + l * NM) +
               w.cross(p_.F_s[l] * eta_dot(x, l));
    Mat3 F;
    if (euler123_F(angles(x), F) != Status::ok) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    return F * (J_inv_ * inner);
  }

  //! Total energy ½ωᵀJω + Σ_l [ωᵀF_sl η̇_l + ½η̇_lᵀη̇_l + ½η_lᵀΩ_l²η_l] [J] (spec B-S5).
  double energy(const State& x) const noexcept {
    const Vec3 w = omega_BN_B(x);
    double E = 0.5 * w.dot(p_.J * w);
    for (int l = 0; l < P; ++l) {
      const Vec<NM> e = eta(x, l), ed = eta_dot(x, l);
      E += w.dot(p_.F_s[l] * ed) + 0.5 * ed.squaredNorm() +
           0.5 * e.dot(p_.Omega[l].cwiseAbs2().cwiseProduct(e));
    }
    return E;
  }

  //! Hub angular momentum H_b = Jω + Σ_l F_sl η̇_l [N m s], B components (spec B-S5).
  Vec3 momentum_B(const State& x) const noexcept {
    Vec3 H = p_.J * omega_BN_B(x);
    for (int l = 0; l < P; ++l) H += p_.F_s[l] * eta_dot(x, l);
    return H;
  }

  //! State at rest modes: ϑ(0) [rad], ϑ̇(0) [rad/s] (ω(0) = G(ϑ(0)) ϑ̇(0), B.4 #16), η = η̇ = 0.
  static State initial_state(const Vec3& angles0, const Vec3& angles_dot0) noexcept {
    State x = State::Zero();
    x.template head<3>() = angles0;
    x.template segment<3>(3) = euler123_G(angles0) * angles_dot0;
    return x;
  }

 private:
  Params p_;
  Mat3 M_eff_ = Mat3::Identity();
  Mat3 M_eff_inv_ = Mat3::Identity();
  Mat3 J_inv_ = Mat3::Identity();
  Status status_ = Status::ok;
};

ADCS_ASSERT_PLANT(FlexibleSpacecraft<2, 4>);

}  // namespace adcs
