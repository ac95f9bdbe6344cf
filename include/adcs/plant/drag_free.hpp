#pragma once
// Drag-free satellite: spacecraft (s/c) attitude, s/c-to-test-mass (TM) relative displacement and
// TM-to-s/c relative attitude, seed 004 eqs. (1)-(3) (spec §B.2), small-angle, linear:
//
//   φ̈_sc  = I_sc⁻¹ (T_Csc + w_TCsc + T_Dsc)                                                seed 004 eq. (1)
//   r̈_rel = −(K_trans/m_tm) r_rel − (D_trans/m_tm) ṙ_rel − (F_Csc + w_FCsc + F_Dsc)/m_sc     seed 004 eq. (2)
//   φ̈_rel = I_tm⁻¹K_rot φ_rel + I_tm⁻¹D_rot φ̇_rel + I_tm⁻¹(T_Ctm + w_TCtm + T_Dtm)
//           − I_sc⁻¹(T_Csc + w_TCsc + T_Dsc)                                               seed 004 eq. (3)
//
// (printed "+" on K_rot, D_rot kept: negative electrostatic stiffness, spec B.10 #13), in the
// extended form of seed 004 eq. (6) with the disturbances f = [T_Dsc; F_Dsc; T_Dtm] appended after each loop
// (27 states, spec §B.2.2), the per-axis accelerometer model (seed 004 eqs. (10)-(13)) with its ±6e-6 m/s² range,
// the exact ZOH discretisation at h (spec §B.3) and the noise densities → per-sample σ.
//
// 0-based state index map (spec §B.2.2): φ_sc 0-2, φ̇_sc 3-5, T_Dsc 6-8, r 9-11, ṙ 12-14,
// F_D 15-17, φ_rel 18-20, φ̇_rel 21-23, T_Dtm 24-26. Inputs u = [T_Csc; F_Csc; T_Ctm] (9).
// Units: rad, m, N, N m, kg, kg m², s.
#include <cmath>
#include <type_traits>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/expm.hpp"

namespace adcs {

inline constexpr int kDragFreeStates = 27;  //!< extended state, seed 004 eq. (6)
inline constexpr int kDragFreeInputs = 9;   //!< [T_Csc; F_Csc; T_Ctm]
inline constexpr int kDragFreeOutputs = 9;  //!< [φ_sc; r_rel; φ_rel] (5)

//! Index of the first component of each 3-block of the extended state (spec §B.2.2).
struct DragFreeIndex {
  static constexpr int phi_sc = 0, phi_sc_dot = 3, T_Dsc = 6, r = 9, r_dot = 12, F_Dsc = 15,
                       phi_rel = 18, phi_rel_dot = 21, T_Dtm = 24;
};

//! Table 2 of seed 004 (every value GIVEN unless marked) and the sensor/actuator data of §4. S is
//! the scalar of whoever reads them (issue 19): the plant, the model below and the filters'
//! design use DragFreeParams (double); a float law (DragFreeAdrcT<float>) reads the values
//! rounded once (cast<float>()).
template <class S = double>
struct DragFreeParamsT {
  using Mat3s = Mat<3, 3, S>;
  S m_tm = S(1.0);                                 //!< [kg] test mass
  S m_sc = S(1050.0);                              //!< [kg] spacecraft
  Mat3s I_tm = S(0.2667e-3) * Mat3s::Identity();   //!< [kg m²]
  Mat3s I_sc = (Mat3s() << 200, 1, 2, 1, 2700, 1, 2, 1, 2650).finished();  //!< [kg m²]
  Mat3s K_trans = S(1e-6) * (Mat3s() << S(1), S(0.039), S(0.039), S(0.039), S(1), S(0.039), S(0.039), S(0.039), S(1))
                                .finished();  //!< [N/m]
  Mat3s D_trans = S(1.4e-11) * Mat3s::Identity();  //!< [N s/m] (printed "N m s/rad", spec B.10 #10)
  Mat3s K_rot = S(1e-9) * (Mat3s() << 1, 10, 10, 10, 1, 10, 10, 10, 1).finished();  //!< [N m/rad]
  Mat3s D_rot = S(1.4e-11) * Mat3s::Identity();    //!< [N m s/rad]
  S period_s = S(0.1);                             //!< [s] h, sample and actuation period
  S accel_min = S(-6e-6);                          //!< [m/s²] accelerometer range y̲
  S accel_max = S(6e-6);                           //!< [m/s²] accelerometer range ȳ
  // One-sided amplitude spectral densities of white noise (spec §B.3, B.10 #4):
  S asd_T_sc = S(1e-8);   //!< [N m/√Hz] w_TCsc
  S asd_F_sc = S(1e-8);   //!< [N/√Hz] w_FCsc
  S asd_T_tm = S(1e-15);  //!< [N m/√Hz] w_TCtm
  S asd_pos = S(1e-8);    //!< [m/√Hz, rad/√Hz] displacement and attitude sensors
  S asd_acc = S(1e-12);   //!< [m s⁻²/√Hz] accelerometer
  bool two_sided_noise = false;  //!< spec §B.3 option: σ² = ASD²/h instead of ASD²/(2h)

  //! The same parameters in the scalar T, each value rounded once (narrow_scalar).
  template <class T>
  DragFreeParamsT<T> cast() const noexcept {
    DragFreeParamsT<T> o;
    o.m_tm = narrow_scalar<T>(m_tm);
    o.m_sc = narrow_scalar<T>(m_sc);
    o.I_tm = scalar_cast<T>(I_tm);
    o.I_sc = scalar_cast<T>(I_sc);
    o.K_trans = scalar_cast<T>(K_trans);
    o.D_trans = scalar_cast<T>(D_trans);
    o.K_rot = scalar_cast<T>(K_rot);
    o.D_rot = scalar_cast<T>(D_rot);
    o.period_s = narrow_scalar<T>(period_s);
    o.accel_min = narrow_scalar<T>(accel_min);
    o.accel_max = narrow_scalar<T>(accel_max);
    o.asd_T_sc = narrow_scalar<T>(asd_T_sc);
    o.asd_F_sc = narrow_scalar<T>(asd_F_sc);
    o.asd_T_tm = narrow_scalar<T>(asd_T_tm);
    o.asd_pos = narrow_scalar<T>(asd_pos);
    o.asd_acc = narrow_scalar<T>(asd_acc);
    o.two_sided_noise = two_sided_noise;
    return o;
  }
};
using DragFreeParams = DragFreeParamsT<double>;

//! True when the parameters define the model: masses finite > 0; I_tm, I_sc symmetric positive
//! definite; K_trans, D_trans, K_rot, D_rot finite (any sign: the printed "+" on K_rot, D_rot is a
//! negative electrostatic stiffness, spec B.10 #13); period_s (h) finite > 0; accel_min < accel_max, both
//! finite; noise densities finite >= 0. drag_free_discretize, drag_free_axis_model and
//! DragFreeAdrc refuse (invalid_parameter) anything else.
template <class S>
bool valid(const DragFreeParamsT<S>& p) noexcept {
  return finite_positive(p.m_tm) && finite_positive(p.m_sc) && symmetric_positive_definite<3, S>(p.I_tm) &&
         symmetric_positive_definite<3, S>(p.I_sc) && all_finite(p.K_trans) && all_finite(p.D_trans) &&
         all_finite(p.K_rot) && all_finite(p.D_rot) && finite_positive(p.period_s) && std::isfinite(p.accel_min) &&
         std::isfinite(p.accel_max) && p.accel_min < p.accel_max && finite_nonnegative(p.asd_T_sc) &&
         finite_nonnegative(p.asd_F_sc) && finite_nonnegative(p.asd_T_tm) && finite_nonnegative(p.asd_pos) &&
         finite_nonnegative(p.asd_acc);
}

//! σ of a ZOH white sequence whose low-frequency one-sided PSD is asd²: σ² = asd²/(2h)
//! (spec §B.3); the two-sided reading gives σ² = asd²/h.
inline double asd_to_sigma(double asd, double h, bool two_sided) noexcept {
  return asd * std::sqrt(two_sided ? 1.0 / h : 0.5 / h);
}

//! Per-sample noise standard deviations derived from the densities.
struct DragFreeNoise {
  double sigma_T_sc, sigma_F_sc, sigma_T_tm, sigma_pos, sigma_acc;
};
inline DragFreeNoise drag_free_noise(const DragFreeParams& p) noexcept {
  const bool t = p.two_sided_noise;
  return DragFreeNoise{asd_to_sigma(p.asd_T_sc, p.period_s, t), asd_to_sigma(p.asd_F_sc, p.period_s, t),
                       asd_to_sigma(p.asd_T_tm, p.period_s, t), asd_to_sigma(p.asd_pos, p.period_s, t),
                       asd_to_sigma(p.asd_acc, p.period_s, t)};
}

//! Continuous extended model, seed 004 eq. (6): Ẋ = A X + B(u + w) + B_e ḟ, Y = C X + d (spec §B.2.2).
struct DragFreeContinuous {
  Mat<27, 27> A = Mat<27, 27>::Zero();
  Mat<27, 9> B = Mat<27, 9>::Zero();
  Mat<27, 9> B_e = Mat<27, 9>::Zero();
  Mat<9, 27> C = Mat<9, 27>::Zero();
};

//! The model builders below are templates on the parameters' scalar only so that including this
//! header compiles none of them (the 27-state ZOH: expm of a 36 x 36 matrix) unless called; they
//! build the model in double, for the plant and the filters' design (a float filter gets the
//! result rounded once, EskfParams::cast).
template <class S>
inline constexpr bool kDragFreeModelInDouble = std::is_same_v<S, double>;

//! A, B, B_e, C of seed 004 eq. (6) from (4) with f moved into the state (block indices 0..8 of 3 x 3).
template <class S = double>
DragFreeContinuous drag_free_continuous(const DragFreeParamsT<S>& p) noexcept {
  static_assert(kDragFreeModelInDouble<S>, "the drag-free model is built in double (cast the result)");
  DragFreeContinuous m;
  const Mat3 I = Mat3::Identity();
  const Mat3 Isc_inv = p.I_sc.inverse(), Itm_inv = p.I_tm.inverse();
  auto A = [&](int i, int j) { return m.A.block<3, 3>(3 * i, 3 * j); };
  auto B = [&](int i, int j) { return m.B.block<3, 3>(3 * i, 3 * j); };
  A(0, 1) = I;
  A(1, 2) = Isc_inv;                                                         // seed 004 eq. (1)
  A(3, 4) = I;
  A(4, 3) = -p.K_trans / p.m_tm;                                             // seed 004 eq. (2)
  A(4, 4) = -p.D_trans / p.m_tm;
  A(4, 5) = -I / p.m_sc;
  A(6, 7) = I;
  A(7, 6) = Itm_inv * p.K_rot;                                               // seed 004 eq. (3), printed "+"
  A(7, 7) = Itm_inv * p.D_rot;
  A(7, 2) = -Isc_inv;
  A(7, 8) = Itm_inv;
  B(1, 0) = Isc_inv;
  B(4, 1) = -I / p.m_sc;
  B(7, 0) = -Isc_inv;
  B(7, 2) = Itm_inv;
  for (int i = 0; i < 3; ++i) m.B_e.block<3, 3>(3 * (3 * i + 2), 3 * i) = I;  // f after each loop
  for (int i = 0; i < 3; ++i) m.C.block<3, 3>(3 * i, 9 * i) = I;             // φ_sc, r, φ_rel
  return m;
}

//! Discrete model at h: [[A_d, B_d],[0, I]] = expm([[A, B],[0, 0]] h), C_d = C, and the discrete
//! B_e is the continuous selector (f is piecewise constant and jumps by G_k at samples, §B.3).   seed 004 eq. (8)
struct DragFreeDiscrete {
  Mat<27, 27> A_d = Mat<27, 27>::Identity();
  Mat<27, 9> B_d = Mat<27, 9>::Zero();
  Mat<27, 9> B_e = Mat<27, 9>::Zero();
  Mat<9, 27> C_d = Mat<9, 27>::Zero();
};

//! invalid_parameter (out untouched) unless valid(p).
template <class S = double>
[[nodiscard]] Status drag_free_discretize(const DragFreeParamsT<S>& p, DragFreeDiscrete& out) noexcept {
  static_assert(kDragFreeModelInDouble<S>, "the drag-free model is built in double (cast the result)");
  if (!valid(p)) return Status::invalid_parameter;
  const DragFreeContinuous c = drag_free_continuous(p);
  DragFreeDiscrete d;
  const Status s = zoh_discretize<27, 9>(c.A, c.B, p.period_s, d.A_d, d.B_d);
  if (s != Status::ok) return s;
  d.B_e = c.B_e;
  d.C_d = c.C;
  out = d;
  return Status::ok;
}

//! Per-axis accelerometer model, seed 004 eqs. (10)-(13), X = [r_j; ṙ_j; f_j], y = C X + D(u + w) + d, with
//! the diagonal K_trans, D_trans only (spec §B.2.3 [A]: the 0.039e-6 N/m couplings go into f).
struct DragFreeAxisModel {
  Mat3 A_d = Mat3::Identity();
  Vec3 B_d = Vec3::Zero();
  Vec3 B_e = Vec3(0.0, 0.0, 1.0);
  Eigen::RowVector3d C = Eigen::RowVector3d::Zero();  //!< [K/m_tm, D/m_tm, 1/m_sc]
  double D = 0.0;                                     //!< [1/kg] 1/m_sc
};

//! invalid_parameter (out untouched) for an axis outside 0..2 or unless valid(p).
template <class S = double>
[[nodiscard]] Status drag_free_axis_model(const DragFreeParamsT<S>& p, int axis, DragFreeAxisModel& out) noexcept {
  static_assert(kDragFreeModelInDouble<S>, "the drag-free model is built in double (cast the result)");
  if (axis < 0 || axis > 2 || !valid(p)) return Status::invalid_parameter;
  const double K = p.K_trans(axis, axis), D = p.D_trans(axis, axis);
  Mat3 A = Mat3::Zero();  // seed 004 eq. (12): [[A_o, B_o],[0, 0]]
  A(0, 1) = 1.0;
  A(1, 0) = -K / p.m_tm;
  A(1, 1) = -D / p.m_tm;
  A(1, 2) = -1.0 / p.m_sc;
  Mat<3, 1> B;
  B << 0.0, -1.0 / p.m_sc, 0.0;
  DragFreeAxisModel m;
  Mat<3, 1> B_d;
  const Status s = zoh_discretize<3, 1>(A, B, p.period_s, m.A_d, B_d);
  if (s != Status::ok) return s;
  m.B_d = B_d;
  m.C << K / p.m_tm, D / p.m_tm, 1.0 / p.m_sc;  // seed 004 eq. (11) C = [C_o, D_o]
  m.D = 1.0 / p.m_sc;
  out = m;
  return Status::ok;
}

//! True accelerometer reading before noise and saturation, axis j, from the 27-state X and the
//! applied force plus its noise (F_Csc + w_FCsc): y = (K_trans r + D_trans ṙ)_j/m_tm +
//! (F_Csc + w_FCsc + F_Dsc)_j/m_sc (= −r̈_rel,j; full 3 x 3 K_trans, D_trans).   seed 004 eq. (11)
inline double drag_free_accelerometer(const DragFreeParams& p, const Vec<27>& X, const Vec3& F_applied,
                                      int axis) noexcept {
  using Ix = DragFreeIndex;
  const Vec3 r = X.segment<3>(Ix::r), rd = X.segment<3>(Ix::r_dot), F_D = X.segment<3>(Ix::F_Dsc);
  return (p.K_trans.row(axis).dot(r) + p.D_trans.row(axis).dot(rd)) / p.m_tm +
         (F_applied(axis) + F_D(axis)) / p.m_sc;
}

//! Test-mass residual acceleration a_tm = −(K_trans r + D_trans ṙ)/m_tm [m/s²] (spec §B.2.1).
inline Vec3 drag_free_tm_acceleration(const DragFreeParams& p, const Vec<27>& X) noexcept {
  using Ix = DragFreeIndex;
  return -(p.K_trans * X.segment<3>(Ix::r) + p.D_trans * X.segment<3>(Ix::r_dot)) / p.m_tm;
}

//! Accelerometer saturation, seed 004 eq. (14): y_c = clamp(y, y̲, ȳ).
inline double saturate_accelerometer(const DragFreeParams& p, double y) noexcept {
  return y > p.accel_max ? p.accel_max : (y < p.accel_min ? p.accel_min : y);
}

}  // namespace adcs
