#pragma once
// The shared signal vocabulary of every component (issue 17): what a torque law reads and writes,
// what an actuation stage takes and gives, what a sensor delivers. Frames and units are in the
// names (Basilisk style: sigma_BN is B relative to N, omega_BN_B that rate in B components,
// `_Nm`, `_rad_s` the unit), so a law written against these types drives any actuation and any
// plant whose adapter produces them.
//
// One attitude signal, three views: AttitudeState (MRP, the library's native form),
// AttitudeStateQuaternion and AttitudeStateEuler123, with exact conversions between them. The
// same for the reference: AttitudeReference (MRP with the inertial rate and acceleration),
// MrpReferenceSample (MRP and its derivatives, seed 001's form) and EulerReferenceSample (x-y-z
// Euler angles and their derivatives, seed 002's form).
//
// Scalar (issue 19): each signal is a template on its scalar, `NameT<S = double>` with the old
// name kept for double (`AttitudeState = AttitudeStateT<double>`); a signal's cast<T>() gives the
// same signal in another scalar (a float law in a double closed loop converts at its boundary).
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/euler.hpp"
#include "adcs/math/mrp.hpp"
#include "adcs/math/quaternion.hpp"

namespace adcs {

// ---------------------------------------------------------------------------------------------
// Attitude state

//! Attitude and rate of the body B relative to the inertial frame N, MRP view.
template <class S = double>
struct AttitudeStateT {
  Vec<3, S> sigma_BN = Vec<3, S>::Zero();    //!< [-] attitude MRP
  Vec<3, S> omega_BN_B = Vec<3, S>::Zero();  //!< [rad/s] body rate, B components
  template <class T>
  AttitudeStateT<T> cast() const noexcept {
    return {scalar_cast<T>(sigma_BN), scalar_cast<T>(omega_BN_B)};
  }
};
using AttitudeState = AttitudeStateT<double>;

//! The same signal, quaternion view (scalar first).
template <class S = double>
struct AttitudeStateQuaternionT {
  QuaternionSFT<S> q_BN = QuaternionSFT<S>::identity();  //!< [-] attitude quaternion, scalar first
  Vec<3, S> omega_BN_B = Vec<3, S>::Zero();              //!< [rad/s] body rate, B components
  template <class T>
  AttitudeStateQuaternionT<T> cast() const noexcept {
    return {q_BN.template cast<T>(), scalar_cast<T>(omega_BN_B)};
  }
};
using AttitudeStateQuaternion = AttitudeStateQuaternionT<double>;

//! The same signal, x-y-z (1-2-3) Euler-angle view (seed 002's state).
template <class S = double>
struct AttitudeStateEuler123T {
  Vec<3, S> theta_BN_rad = Vec<3, S>::Zero();  //!< [rad] ϑ, x-y-z Euler angles of B relative to N
  Vec<3, S> omega_BN_B = Vec<3, S>::Zero();    //!< [rad/s] body rate, B components
  template <class T>
  AttitudeStateEuler123T<T> cast() const noexcept {
    return {scalar_cast<T>(theta_BN_rad), scalar_cast<T>(omega_BN_B)};
  }
};
using AttitudeStateEuler123 = AttitudeStateEuler123T<double>;

template <class S>
inline AttitudeStateQuaternionT<S> to_quaternion(const AttitudeStateT<S>& x) noexcept {
  return AttitudeStateQuaternionT<S>{mrp_to_quat(x.sigma_BN), x.omega_BN_B};
}
template <class S>
inline AttitudeStateT<S> to_mrp(const AttitudeStateQuaternionT<S>& x) noexcept {
  return AttitudeStateT<S>{quat_to_mrp(x.q_BN.canonical()), x.omega_BN_B};  // |σ| ≤ 1
}
template <class S>
inline AttitudeStateEuler123T<S> to_euler123(const AttitudeStateT<S>& x) noexcept {
  return AttitudeStateEuler123T<S>{dcm_to_euler123(mrp_to_dcm(x.sigma_BN)), x.omega_BN_B};
}
template <class S>
inline AttitudeStateT<S> to_mrp(const AttitudeStateEuler123T<S>& x) noexcept {
  return AttitudeStateT<S>{dcm_to_mrp(euler123_to_dcm(x.theta_BN_rad)), x.omega_BN_B};
}

// ---------------------------------------------------------------------------------------------
// Attitude reference

//! Reference attitude R with its inertial rate and acceleration (Basilisk's attRefMsg).
template <class S = double>
struct AttitudeReferenceT {
  Vec<3, S> sigma_RN = Vec<3, S>::Zero();     //!< [-] reference attitude MRP
  Vec<3, S> omega_RN_N = Vec<3, S>::Zero();   //!< [rad/s] reference rate, N components
  Vec<3, S> domega_RN_N = Vec<3, S>::Zero();  //!< [rad/s²] reference angular acceleration, N components
  template <class T>
  AttitudeReferenceT<T> cast() const noexcept {
    return {scalar_cast<T>(sigma_RN), scalar_cast<T>(omega_RN_N), scalar_cast<T>(domega_RN_N)};
  }
};
using AttitudeReference = AttitudeReferenceT<double>;

//! Reference as an MRP and its derivatives (seed 001's form: the law tracks σ̈_d directly).
template <class S = double>
struct MrpReferenceSampleT {
  Vec<3, S> sigma = Vec<3, S>::Zero();       //!< [-] σ_d (σ_RN)
  Vec<3, S> sigma_dot = Vec<3, S>::Zero();   //!< [1/s] σ̇_d
  Vec<3, S> sigma_ddot = Vec<3, S>::Zero();  //!< [1/s²] σ̈_d
  Vec<3, S> omega = Vec<3, S>::Zero();       //!< [rad/s] ω_f = ω_RN, R components
  Vec<3, S> omega_dot = Vec<3, S>::Zero();   //!< [rad/s²] ω̇_f, R components
  template <class T>
  MrpReferenceSampleT<T> cast() const noexcept {
    return {scalar_cast<T>(sigma), scalar_cast<T>(sigma_dot), scalar_cast<T>(sigma_ddot),
            scalar_cast<T>(omega), scalar_cast<T>(omega_dot)};
  }
};
using MrpReferenceSample = MrpReferenceSampleT<double>;

//! Reference as x-y-z Euler angles and their derivatives (seed 002's form).
template <class S = double>
struct EulerReferenceSampleT {
  Vec<3, S> angles = Vec<3, S>::Zero();       //!< [rad] ϑ_d (x-y-z)
  Vec<3, S> angles_dot = Vec<3, S>::Zero();   //!< [rad/s] ϑ̇_d
  Vec<3, S> angles_ddot = Vec<3, S>::Zero();  //!< [rad/s²] ϑ̈_d
  template <class T>
  EulerReferenceSampleT<T> cast() const noexcept {
    return {scalar_cast<T>(angles), scalar_cast<T>(angles_dot), scalar_cast<T>(angles_ddot)};
  }
};
using EulerReferenceSample = EulerReferenceSampleT<double>;

//! MRP-derivative view → inertial-rate view: ω_RN_N = C_RNᵀ ω_f; ω̇ is the same seen from R and
//! from N (ω × ω = 0), so domega_RN_N = C_RNᵀ ω̇_f.
template <class S>
inline AttitudeReferenceT<S> to_attitude_reference(const MrpReferenceSampleT<S>& r) noexcept {
  const Mat<3, 3, S> C_RN = mrp_to_dcm(r.sigma);
  return AttitudeReferenceT<S>{r.sigma, C_RN.transpose() * r.omega, C_RN.transpose() * r.omega_dot};
}

//! Inertial-rate view → MRP-derivative view: σ̇ = G(σ) ω_R, σ̈ = Ġ(σ, σ̇) ω_R + G(σ) ω̇_R.
template <class S>
inline MrpReferenceSampleT<S> to_mrp_reference(const AttitudeReferenceT<S>& r) noexcept {
  const Mat<3, 3, S> C_RN = mrp_to_dcm(r.sigma_RN);
  MrpReferenceSampleT<S> s;
  s.sigma = r.sigma_RN;
  s.omega = C_RN * r.omega_RN_N;
  s.omega_dot = C_RN * r.domega_RN_N;
  s.sigma_dot = mrp_G(s.sigma) * s.omega;
  s.sigma_ddot = mrp_G_dot(s.sigma, s.sigma_dot) * s.omega + mrp_G(s.sigma) * s.omega_dot;
  return s;
}

//! Inertial-rate view → Euler view: ϑ from C_RN, ϑ̇ = F(ϑ) ω_R, ϑ̈ = F(ϑ)(ω̇_R − Ġ(ϑ, ϑ̇) ϑ̇) with
//! ω = G(ϑ) ϑ̇. singular at gimbal lock (|cos ϑ_2| tiny), the output then untouched.
template <class S>
[[nodiscard]] inline Status to_euler_reference(const AttitudeReferenceT<S>& r, EulerReferenceSampleT<S>& out) noexcept {
  const Mat<3, 3, S> C_RN = mrp_to_dcm(r.sigma_RN);
  const Vec<3, S> angles = dcm_to_euler123(C_RN);
  Mat<3, 3, S> F;
  const Status s = euler123_F(angles, F);
  if (s != Status::ok) return s;
  const Vec<3, S> w = C_RN * r.omega_RN_N, w_dot = C_RN * r.domega_RN_N;
  out.angles = angles;
  out.angles_dot = F * w;
  out.angles_ddot = F * (w_dot - euler123_G_dot(angles, out.angles_dot) * out.angles_dot);
  return Status::ok;
}

// ---------------------------------------------------------------------------------------------
// Commands

//! A torque request on the body (what every attitude torque law outputs).
template <class S = double>
struct BodyTorqueT {
  Vec<3, S> torque_B_Nm = Vec<3, S>::Zero();  //!< [N m] control torque, B components
  template <class T>
  BodyTorqueT<T> cast() const noexcept {
    return {scalar_cast<T>(torque_B_Nm)};
  }
};
using BodyTorque = BodyTorqueT<double>;

//! A force and torque request on the body (what the SE(3) laws output); the stacked order
//! [torque; force] is seed 003's u = [M; F].
template <class S = double>
struct WrenchT {
  Vec<3, S> torque_B_Nm = Vec<3, S>::Zero();  //!< [N m] control torque, B components
  Vec<3, S> force_B_N = Vec<3, S>::Zero();    //!< [N] control force, B components
  Vec<6, S> stacked() const noexcept { return stack3(torque_B_Nm, force_B_N); }
  static WrenchT from_stacked(const Vec<6, S>& u) noexcept {
    return WrenchT{u.template head<3>(), u.template tail<3>()};
  }
  template <class T>
  WrenchT<T> cast() const noexcept {
    return {scalar_cast<T>(torque_B_Nm), scalar_cast<T>(force_B_N)};
  }
};
using Wrench = WrenchT<double>;

//! Motor torques of N reaction wheels about their spin axes.
template <int N, class S = double>
struct WheelTorques {
  Vec<N, S> u_s_Nm = Vec<N, S>::Zero();  //!< [N m] motor torque on each wheel
  template <class T>
  WheelTorques<N, T> cast() const noexcept {
    return {scalar_cast<T>(u_s_Nm)};
  }
};

//! Rates of M CMG gimbals and accelerations of N wheels (a VSCMG cluster's input).   seed 001 eq. (12)
template <int M, int N, class S = double>
struct VscmgRates {
  Vec<M, S> gamma_dot_rad_s = Vec<M, S>::Zero();   //!< [rad/s] gimbal rates
  Vec<N, S> Omega_dot_rad_s2 = Vec<N, S>::Zero();  //!< [rad/s²] wheel accelerations
  //! [γ̇ (M); Ω̇_w (N)], the plant's input order.
  Vec<M + N, S> stacked() const noexcept {
    Vec<M + N, S> u;
    u.template head<M>() = gamma_dot_rad_s;
    u.template tail<N>() = Omega_dot_rad_s2;
    return u;
  }
  static VscmgRates from_stacked(const Vec<M + N, S>& u) noexcept {
    return VscmgRates{u.template head<M>(), u.template tail<N>()};
  }
  template <class T>
  VscmgRates<M, N, T> cast() const noexcept {
    return {scalar_cast<T>(gamma_dot_rad_s), scalar_cast<T>(Omega_dot_rad_s2)};
  }
};

// ---------------------------------------------------------------------------------------------
// Actuator and sensor samples

//! State of a VSCMG cluster as measured: gimbal angles and wheel speeds.
template <int M, int N, class S = double>
struct VscmgState {
  Vec<M, S> gamma_rad = Vec<M, S>::Zero();    //!< [rad] gimbal angles
  Vec<N, S> Omega_rad_s = Vec<N, S>::Zero();  //!< [rad/s] wheel speeds relative to the body
  template <class T>
  VscmgState<M, N, T> cast() const noexcept {
    return {scalar_cast<T>(gamma_rad), scalar_cast<T>(Omega_rad_s)};
  }
};

//! A rate-gyro sample.
template <class S = double>
struct GyroSampleT {
  double t_s = 0.0;                          //!< [s] sample time (double in every instance: a mission clock)
  Vec<3, S> omega_BN_B = Vec<3, S>::Zero();  //!< [rad/s] measured body rate
  bool valid = true;                         //!< false: no sample this period (dropout)
};
using GyroSample = GyroSampleT<double>;

//! A star-tracker sample.
template <class S = double>
struct StarTrackerSampleT {
  double t_s = 0.0;                                      //!< [s] sample time (mission clock, double)
  QuaternionSFT<S> q_BN = QuaternionSFT<S>::identity();  //!< [-] measured attitude
  bool valid = true;                                     //!< false: no solution this period
};
using StarTrackerSample = StarTrackerSampleT<double>;

//! K accelerometer axes (seed 004's saturated electrostatic accelerometers).
template <int K, class S = double>
struct AccelerometerSample {
  double t_s = 0.0;                      //!< [s] sample time (mission clock, double)
  Vec<K, S> a_m_s2 = Vec<K, S>::Zero();  //!< [m/s²] readings (possibly at the range limit)
};

}  // namespace adcs
