#pragma once
// Cluster of M single-gimbal control moment gyros (CMGs) and N reaction wheels (a hybrid
// variable-speed CMG cluster), seed 001 eqs. (1)-(3), and two truth plants built on it:
//
//   VscmgFullPlant<M,N>  TP-FULL (spec A.2.4): the full model (FULL) in momentum form, exact
//                        incl. J_dot omega and the gimbal momentum; conserves C(sigma)^T h.
//   VscmgCtrlPlant<M,N>  TP-CTRL (spec A.2.4): seed 001 eq. (5) with constant J = J_n and the
//                        true (deviated) axes; for unit tests of the controller algebra.
//
// Symbols (seed 001 / spec A.1), all in body (B) components:
//   g_i, s_i, t_i   gimbal axis, rotor spin axis, transverse axis of CMG i; t = g x s
//   A_cg, A_cs, A_ct [g_1..g_M], [s_1..s_M], [t_1..t_M]; A_cs0, A_ct0 at gimbal angle gamma = 0
//   A_ws             [s_w1..s_wN] wheel spin axes (constant)
//   h_cw,i           rotor angular-momentum magnitude of CMG i (rotor speed constant)
//   I_cs, I_ct, I_cg gimbal + rotor inertia of CMG i about s, t, g
//   I_wws,j          spin inertia of wheel j; Omega_w,j its speed relative to the body
//   J_s              body inertia incl. actuators as point masses and wheel transverse inertia
//   J_tr(gamma)      total inertia, seed 001 eq. (2) specialised to the hybrid cluster
// The axes are NOT required to be unit or orthogonal: installation deviations (Mode A, spec
// A.2.3) are added elementwise without renormalisation, exactly as the paper parameterises them.
#include <type_traits>

#include <Eigen/Cholesky>

#include "adcs/core/failure_hook.hpp"
#include "adcs/core/plant.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/mrp.hpp"
#include "adcs/math/so3.hpp"

namespace adcs {

//! Geometry and inertias of a cluster of M CMGs and N reaction wheels. The axes, rotor momenta,
//! wheel inertias and J_s have no default: NaN until set (set_cmg_pyramid, wheel_pyramid_axes,
//! pyramid_4cmg_3rw_nominal), so a forgotten one is refused by every plant and controller that
//! validates the geometry. The gimbal+rotor inertias I_cs, I_ct, I_cg default to 0: lumped into
//! J_s, as the controller model of seed 001 eq. (5) has them.
template <int M, int N, class S = double>
struct VscmgGeometry {
  static_assert(M >= 1 && N >= 0, "VscmgGeometry: need M >= 1 CMGs and N >= 0 wheels (N = 0: a pure CMG cluster)");
  using Mat3S = Mat<3, 3, S>;
  Mat<3, M, S> A_cg = Mat<3, M, S>::Constant(unset_v<S>);   //!< [-] gimbal axes g_i (columns), constant
  Mat<3, M, S> A_cs0 = Mat<3, M, S>::Constant(unset_v<S>);  //!< [-] rotor spin axes s_i0 at gamma_i = 0
  Mat<3, M, S> A_ct0 = Mat<3, M, S>::Constant(unset_v<S>);  //!< [-] transverse axes t_i0 at gamma_i = 0
  Mat<3, N, S> A_ws = Mat<3, N, S>::Constant(unset_v<S>);   //!< [-] wheel spin axes s_wj (columns)
  Vec<M, S> I_cs = Vec<M, S>::Zero();         //!< [kg m^2] CMG gimbal+rotor inertia about s_i (0: in J_s)
  Vec<M, S> I_ct = Vec<M, S>::Zero();         //!< [kg m^2] CMG gimbal+rotor inertia about t_i (0: in J_s)
  Vec<M, S> I_cg = Vec<M, S>::Zero();         //!< [kg m^2] CMG gimbal+rotor inertia about g_i (0: in J_s)
  Vec<M, S> h_cw = Vec<M, S>::Constant(unset_v<S>);  //!< [N m s] CMG rotor momentum h_cw,i = I_cws,i Omega_c,i
  Vec<N, S> I_wws = Vec<N, S>::Constant(unset_v<S>);  //!< [kg m^2] wheel spin inertias
  Mat3S J_s = Mat3S::Constant(unset_v<S>);    //!< [kg m^2] body inertia (see header comment), SPD

  //! The same geometry in another scalar (each value rounded once, issue 19).
  template <class T>
  VscmgGeometry<M, N, T> cast() const noexcept {
    VscmgGeometry<M, N, T> g;
    g.A_cg = scalar_cast<T>(A_cg);
    g.A_cs0 = scalar_cast<T>(A_cs0);
    g.A_ct0 = scalar_cast<T>(A_ct0);
    g.A_ws = scalar_cast<T>(A_ws);
    g.I_cs = scalar_cast<T>(I_cs);
    g.I_ct = scalar_cast<T>(I_ct);
    g.I_cg = scalar_cast<T>(I_cg);
    g.h_cw = scalar_cast<T>(h_cw);
    g.I_wws = scalar_cast<T>(I_wws);
    g.J_s = scalar_cast<T>(J_s);
    return g;
  }

  //! A_cs(gamma) = A_cs0 diag(cos gamma) + A_ct0 diag(sin gamma).   seed 001 eq. (3)
  Mat<3, M, S> A_cs(const Vec<M, S>& gamma) const noexcept {
    Mat<3, M, S> A;
    for (int i = 0; i < M; ++i)
      A.col(i) = std::cos(gamma(i)) * A_cs0.col(i) + std::sin(gamma(i)) * A_ct0.col(i);
    return A;
  }
  //! A_ct(gamma) = A_ct0 diag(cos gamma) - A_cs0 diag(sin gamma).   seed 001 eq. (3)
  Mat<3, M, S> A_ct(const Vec<M, S>& gamma) const noexcept {
    Mat<3, M, S> A;
    for (int i = 0; i < M; ++i)
      A.col(i) = std::cos(gamma(i)) * A_ct0.col(i) - std::sin(gamma(i)) * A_cs0.col(i);
    return A;
  }
  //! J_tr(gamma) = J_s + sum_i [I_cs s s^T + I_ct t t^T + I_cg g g^T]_i + sum_j I_wws s_w s_w^T
  //! [kg m^2].   seed 001 eq. (2), spec A.2.4
  Mat3S J_tr(const Vec<M, S>& gamma) const noexcept {
    const Mat<3, M, S> Sc = A_cs(gamma);
    const Mat<3, M, S> T = A_ct(gamma);
    Mat3S J = J_s;
    for (int i = 0; i < M; ++i) {
      J += I_cs(i) * Sc.col(i) * Sc.col(i).transpose();
      J += I_ct(i) * T.col(i) * T.col(i).transpose();
      J += I_cg(i) * A_cg.col(i) * A_cg.col(i).transpose();
    }
    if constexpr (N > 0)  // a pure CMG cluster has no wheel columns to take
      for (int j = 0; j < N; ++j) J += I_wws(j) * A_ws.col(j) * A_ws.col(j).transpose();
    return J;
  }
  //! Q_act(gamma) = [A_ct(gamma) H_cw, A_ws I_wws] [N m s | kg m^2]: torque per unit input
  //! (with a minus sign).   seed 001 eq. (11)
  Mat<3, M + N, S> Q_act(const Vec<M, S>& gamma) const noexcept {
    Mat<3, M + N, S> Q;
    const Mat<3, M, S> T = A_ct(gamma);
    for (int i = 0; i < M; ++i) Q.col(i) = h_cw(i) * T.col(i);
    if constexpr (N > 0)
      for (int j = 0; j < N; ++j) Q.col(M + j) = I_wws(j) * A_ws.col(j);
    return Q;
  }
  //! Internal (actuator) momentum A_cs h_cw + A_cg I_cg gamma_dot + A_ws I_wws Omega_w [N m s].
  //! seed 001 eq. (1)
  Vec<3, S> internal_momentum(const Vec<M, S>& gamma, const Vec<M, S>& gamma_dot,
                              const Vec<N, S>& Omega_w) const noexcept {
    Vec<3, S> H = A_cs(gamma) * h_cw + A_cg * I_cg.cwiseProduct(gamma_dot);
    // A pure CMG cluster has no wheel term: a product with the empty 3x0 A_ws would do pointer
    // arithmetic on its null data (undefined behaviour UBSan reports), so it is not formed.
    if constexpr (N > 0) H += A_ws * I_wws.cwiseProduct(Omega_w);
    return H;
  }
};

//! Installation deviations (true - nominal) of the axis matrices.   spec A.2.3
template <int M, int N>
struct VscmgDeviation {
  Mat<3, M> dA_cs0 = Mat<3, M>::Zero();  //!< [-] Delta A_cs0
  Mat<3, M> dA_ct0 = Mat<3, M>::Zero();  //!< [-] Delta A_ct0
  Mat<3, N> dA_ws = Mat<3, N>::Zero();   //!< [-] Delta A_ws
  Mat<3, M> dA_cg = Mat<3, M>::Zero();   //!< [-] Delta A_cg (optional; 0 = gimbal axes exact)

  //! Theta_cGi = [Delta t_i0; Delta s_i0] (CMG i deviation parameter).   seed 001 eq. (19)
  Vec6 theta_cG(int i) const noexcept {
    Vec6 th;
    th << dA_ct0.col(i), dA_cs0.col(i);
    return th;
  }
  //! Theta_wGj = Delta s_wj (wheel j deviation parameter).   seed 001 eq. (20)
  Vec3 theta_wG(int j) const noexcept { return dA_ws.col(j); }
};

//! True geometry = nominal + deviation, elementwise, NOT renormalised (Mode A, spec A.2.3).
template <int M, int N>
inline VscmgGeometry<M, N> apply_deviation(const VscmgGeometry<M, N>& nominal,
                                           const VscmgDeviation<M, N>& dev) noexcept {
  VscmgGeometry<M, N> g = nominal;
  g.A_cs0 += dev.dA_cs0;
  g.A_ct0 += dev.dA_ct0;
  g.A_ws += dev.dA_ws;
  g.A_cg += dev.dA_cg;
  return g;
}

//! Mode B deviations (spec A.2.3, optional, physically rigid): each CMG triad (g_i, s_i0, t_i0)
//! is rotated by exp([φ_c,i]x) and each wheel axis s_wj by exp([φ_w,j]x); the deviation is the
//! rotated minus the nominal vector, so it stays inside the paper's parameterisation.
//! φ_c (3 x M) and φ_w (3 x N) are rotation vectors [rad], columns per actuator.
template <int M, int N>
inline VscmgDeviation<M, N> rigid_mounting_deviation(const VscmgGeometry<M, N>& nominal,
                                                     const Mat<3, M>& phi_c,
                                                     const Mat<3, N>& phi_w) noexcept {
  VscmgDeviation<M, N> d;
  for (int i = 0; i < M; ++i) {
    const Mat3 R = so3_exp(phi_c.col(i)) - Mat3::Identity();
    d.dA_cg.col(i) = R * nominal.A_cg.col(i);
    d.dA_cs0.col(i) = R * nominal.A_cs0.col(i);
    d.dA_ct0.col(i) = R * nominal.A_ct0.col(i);
  }
  for (int j = 0; j < N; ++j) d.dA_ws.col(j) = (so3_exp(phi_w.col(j)) - Mat3::Identity()) * nominal.A_ws.col(j);
  return d;
}

//! True geometry (used by the plant) and nominal geometry (the only one a controller sees).
template <int M, int N>
struct VscmgParams {
  VscmgGeometry<M, N> truth;
  VscmgGeometry<M, N> nominal;
};

namespace detail {
//! Validity of a geometry: finite, J_s symmetric positive definite, inertias >= 0, h_cw >= 0.
//! Then J_tr(gamma) is SPD for every gamma (a sum of J_s and PSD terms).
template <int M, int N, class S>
inline bool vscmg_geometry_valid(const VscmgGeometry<M, N, S>& g) noexcept {
  bool ok = all_finite(g.A_cg) && all_finite(g.A_cs0) && all_finite(g.A_ct0) &&
            all_finite(g.A_ws) && all_finite(g.I_cs) && all_finite(g.I_ct) &&
            all_finite(g.I_cg) && all_finite(g.h_cw) && all_finite(g.I_wws) && all_finite(g.J_s);
  if (!ok) return false;
  ok = (g.I_cs.array() >= S(0)).all() && (g.I_ct.array() >= S(0)).all() &&
       (g.I_cg.array() >= S(0)).all() && (g.h_cw.array() >= S(0)).all() &&
       (g.I_wws.array() >= S(0)).all();
  if (!ok) return false;
  // Symmetric to rounding of the scalar: 1e-12 relative in double, 1e-5 in float.
  const S sym_tol = std::is_same_v<S, double> ? S(1e-12) : S(1e-5);
  if ((g.J_s - g.J_s.transpose()).norm() > sym_tol * g.J_s.norm()) return false;
  const Eigen::LLT<Mat<3, 3, S>> llt(g.J_s);
  return llt.info() == Eigen::Success;
}
}  // namespace detail

//! True when the geometry is set and physical (see detail::vscmg_geometry_valid): what the plants
//! and HybridAdaptive check at construction.
template <int M, int N, class S>
inline bool valid(const VscmgGeometry<M, N, S>& g) noexcept {
  return detail::vscmg_geometry_valid(g);
}

//! TP-FULL (spec A.2.4): full VSCMG cluster model in momentum form.
//!
//! State  x = [sigma_BN (3) [-]; h_B (3) [N m s] total angular momentum, B components;
//!             gamma (M) [rad] gimbal angles; Omega_w (N) [rad/s] wheel speeds].
//! Input  u = [gamma_dot (M) [rad/s]; Omega_w_dot (N) [rad/s^2]], held (ZOH).
//! External torque tau_ext_B (3) [N m], B components: a member set by the scenario with
//! set_external_torque() (default zero); it is not part of u because the paper's controller
//! never commands it.
//! Model (TRUE geometry everywhere):
//!   omega = J_tr(gamma)^-1 [h - A_cs(gamma) h_cw - A_cg I_cg gamma_dot - A_ws I_wws Omega_w]
//!                                                     seed 001 eq. (1) solved for omega
//!   sigma_dot = G(sigma) omega                        seed 001 eq. (6)
//!   h_dot = -omega x h + tau_ext                      Euler's law (spec A.2.1 (FULL))
//!   gamma_dot = u_1..M,  Omega_w_dot = u_M+1..M+N
//! No normalize(): sigma must stay on one continuous branch (spec A.2.4, no shadow switching).
template <int M, int N>
class VscmgFullPlant {
 public:
  static constexpr int kCmgs = M;
  static constexpr int kWheels = N;
  static constexpr int kStateSize = 6 + M + N;
  static constexpr int kInputSize = M + N;
  using State = Vec<kStateSize>;
  using Input = Vec<kInputSize>;
  using Params = VscmgParams<M, N>;
  using Geometry = VscmgGeometry<M, N>;

  //! Validates both geometries (status() says the outcome; the failure hook is called on error).
  explicit VscmgFullPlant(const Params& p) noexcept : p_(p) {
    const bool ok = detail::vscmg_geometry_valid(p_.truth) && detail::vscmg_geometry_valid(p_.nominal);
    status_ = ADCS_CHECK(ok,
                         "VscmgFullPlant: geometry must be finite, J_s SPD, inertias and h_cw >= 0")
                  ? Status::ok
                  : Status::invalid_parameter;
  }

  //! ok, or invalid_parameter when either geometry is invalid (detail::vscmg_geometry_valid:
  //! every entry finite, i.e. set; J_s symmetric positive definite; inertias and h_cw >= 0).
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }

  //! Sets the external torque tau_ext [N m], B components (held until changed).
  void set_external_torque(const Vec3& tau_ext_B) noexcept { tau_ext_B_ = tau_ext_B; }
  const Vec3& external_torque() const noexcept { return tau_ext_B_; }

  static Vec3 sigma_BN(const State& x) noexcept { return x.template head<3>(); }
  static Vec3 h_B(const State& x) noexcept { return x.template segment<3>(3); }
  static Vec<M> gamma(const State& x) noexcept { return x.template segment<M>(6); }
  static Vec<N> Omega_w(const State& x) noexcept { return x.template tail<N>(); }
  static Vec<M> gamma_dot(const Input& u) noexcept { return u.template head<M>(); }
  static Vec<N> Omega_w_dot(const Input& u) noexcept { return u.template tail<N>(); }

  //! True total inertia J_tr(gamma) [kg m^2] at state x.   seed 001 eq. (2)
  Mat3 J_tr(const State& x) const noexcept { return p_.truth.J_tr(gamma(x)); }

  //! omega_BN_B [rad/s] from the momentum state and the held input (gamma_dot enters through
  //! the gimbal momentum).   spec A.2.4, seed 001 eq. (1)
  Vec3 omega_BN_B(const State& x, const Input& u) const noexcept {
    const Vec<M> g = gamma(x);
    const Mat3 J = p_.truth.J_tr(g);
    const Vec3 rhs = h_B(x) - p_.truth.internal_momentum(g, gamma_dot(u), Omega_w(x));
    return J.llt().solve(rhs);
  }

  //! Total angular momentum in inertial components H_N = C(sigma)^T h [N m s].
  Vec3 momentum_N(const State& x) const noexcept {
    return mrp_to_dcm(sigma_BN(x)).transpose() * h_B(x);
  }

  //! h(0) [N m s] from seed 001 eq. (1) with gamma_dot(0-) = 0 (spec A.2.4 initialisation).
  Vec3 initial_momentum(const Vec3& omega_BN_B0, const Vec<M>& gamma0,
                        const Vec<N>& Omega_w0) const noexcept {
    return Vec3(p_.truth.J_tr(gamma0) * omega_BN_B0 +
                p_.truth.internal_momentum(gamma0, Vec<M>::Zero(), Omega_w0));
  }

  //! Full initial state [sigma0; h(0); gamma0; Omega_w0] (h(0) as initial_momentum()).
  State initial_state(const Vec3& sigma_BN0, const Vec3& omega_BN_B0, const Vec<M>& gamma0,
                      const Vec<N>& Omega_w0) const noexcept {
    State x;
    x.template head<3>() = sigma_BN0;
    x.template segment<3>(3) = initial_momentum(omega_BN_B0, gamma0, Omega_w0);
    x.template segment<M>(6) = gamma0;
    x.template tail<N>() = Omega_w0;
    return x;
  }

  //! A refused plant (status() != ok) has no dynamics: xdot = 0, finite.
  void derivative(double /*t*/, const State& x, const Input& u, State& xdot) const noexcept {
    if (status_ != Status::ok) {
      xdot.setZero();
      return;
    }
    const Vec3 w = omega_BN_B(x, u);
    const Vec3 h = h_B(x);
    xdot.template head<3>() = mrp_G(sigma_BN(x)) * w;        // seed 001 eq. (6)
    xdot.template segment<3>(3) = -w.cross(h) + tau_ext_B_;  // spec A.2.4: h_dot = -w x h + tau
    xdot.template segment<M>(6) = gamma_dot(u);
    xdot.template tail<N>() = Omega_w_dot(u);
  }

 private:
  Params p_;
  Vec3 tau_ext_B_ = Vec3::Zero();  //!< [N m] external torque, B components
  Status status_ = Status::ok;
};

ADCS_ASSERT_PLANT(VscmgFullPlant<4, 3>);

//! TP-CTRL (spec A.2.4): seed 001 eq. (5) with constant inertia J = J_n and TRUE axes.
//!
//! State  x = [sigma_BN (3) [-]; omega_BN_B (3) [rad/s]; gamma (M) [rad]; Omega_w (N) [rad/s]].
//! Input  u = [gamma_dot (M) [rad/s]; Omega_w_dot (N) [rad/s^2]], held (ZOH).
//!   J_n omega_dot = -omega x (J_n omega + A_cs,tr(gamma) H_cw 1 + A_ws,tr I_wws Omega_w)
//!                   - A_ct,tr(gamma) H_cw gamma_dot - A_ws,tr I_wws Omega_w_dot   seed 001 eq. (5)
//! No external torque (the controller model has none). No normalize() (no shadow switching).
template <int M, int N>
class VscmgCtrlPlant {
 public:
  static constexpr int kCmgs = M;
  static constexpr int kWheels = N;
  static constexpr int kStateSize = 6 + M + N;
  static constexpr int kInputSize = M + N;
  using State = Vec<kStateSize>;
  using Input = Vec<kInputSize>;
  using Params = VscmgParams<M, N>;

  //! J_n = J_tr(0) of the NOMINAL geometry (spec A.5, "controller inertia").
  explicit VscmgCtrlPlant(const Params& p) noexcept
      : VscmgCtrlPlant(p, p.nominal.J_tr(Vec<M>::Zero())) {}

  //! Explicit constant inertia J_n [kg m^2] (symmetric positive definite).
  VscmgCtrlPlant(const Params& p, const Mat3& J_n) noexcept : p_(p), J_n_(J_n), llt_(J_n) {
    const bool ok = detail::vscmg_geometry_valid(p_.truth) &&
                    detail::vscmg_geometry_valid(p_.nominal) && all_finite(J_n_) &&
                    (J_n_ - J_n_.transpose()).norm() <= 1e-12 * J_n_.norm() &&
                    llt_.info() == Eigen::Success;
    status_ = ADCS_CHECK(ok, "VscmgCtrlPlant: geometry invalid or J_n not SPD")
                  ? Status::ok
                  : Status::invalid_parameter;
  }

  //! ok, or invalid_parameter when either geometry is invalid (as VscmgFullPlant) or J_n is not
  //! finite, symmetric positive definite.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  //! Constant inertia J_n [kg m^2].
  const Mat3& J_n() const noexcept { return J_n_; }

  static Vec3 sigma_BN(const State& x) noexcept { return x.template head<3>(); }
  static Vec3 omega_BN_B(const State& x) noexcept { return x.template segment<3>(3); }
  static Vec<M> gamma(const State& x) noexcept { return x.template segment<M>(6); }
  static Vec<N> Omega_w(const State& x) noexcept { return x.template tail<N>(); }

  //! h = J_n omega + A_cs,tr(gamma) H_cw 1 + A_ws,tr I_wws Omega_w [N m s].   seed 001 eq. (5)
  Vec3 momentum_B(const State& x) const noexcept {
    return Vec3(J_n_ * omega_BN_B(x) +
                p_.truth.internal_momentum(gamma(x), Vec<M>::Zero(), Omega_w(x)));
  }
  //! H_N = C(sigma)^T h [N m s] (conserved by seed 001 eq. (5)).
  Vec3 momentum_N(const State& x) const noexcept {
    return mrp_to_dcm(sigma_BN(x)).transpose() * momentum_B(x);
  }

  //! A refused plant (status() != ok) has no dynamics: xdot = 0, finite.
  void derivative(double /*t*/, const State& x, const Input& u, State& xdot) const noexcept {
    if (status_ != Status::ok) {
      xdot.setZero();
      return;
    }
    const Vec3 w = omega_BN_B(x);
    const Vec3 h = momentum_B(x);
    const Vec3 torque = -w.cross(h) - p_.truth.Q_act(gamma(x)) * u;  // seed 001 eqs. (5), (11)
    xdot.template head<3>() = mrp_G(sigma_BN(x)) * w;                 // seed 001 eq. (6)
    xdot.template segment<3>(3) = llt_.solve(torque);
    xdot.template segment<M>(6) = u.template head<M>();
    xdot.template tail<N>() = u.template tail<N>();
  }

 private:
  Params p_;
  Mat3 J_n_;
  Eigen::LLT<Mat3> llt_;
  Status status_ = Status::ok;
};

ADCS_ASSERT_PLANT(VscmgCtrlPlant<4, 3>);

}  // namespace adcs
