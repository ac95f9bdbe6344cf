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
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/math/euler.hpp"
#include "adcs/math/mrp.hpp"
#include "adcs/math/quaternion.hpp"

namespace adcs {

// ---------------------------------------------------------------------------------------------
// Attitude state

//! Attitude and rate of the body B relative to the inertial frame N, MRP view.
struct AttitudeState {
  Vec3 sigma_BN = Vec3::Zero();    //!< [-] attitude MRP
  Vec3 omega_BN_B = Vec3::Zero();  //!< [rad/s] body rate, B components
};

//! The same signal, quaternion view (scalar first).
struct AttitudeStateQuaternion {
  QuaternionSF q_BN = QuaternionSF::identity();  //!< [-] attitude quaternion, scalar first
  Vec3 omega_BN_B = Vec3::Zero();                //!< [rad/s] body rate, B components
};

//! The same signal, x-y-z (1-2-3) Euler-angle view (seed 002's state).
struct AttitudeStateEuler123 {
  Vec3 theta_BN_rad = Vec3::Zero();  //!< [rad] ϑ, x-y-z Euler angles of B relative to N
  Vec3 omega_BN_B = Vec3::Zero();    //!< [rad/s] body rate, B components
};

inline AttitudeStateQuaternion to_quaternion(const AttitudeState& x) noexcept {
  return AttitudeStateQuaternion{mrp_to_quat(x.sigma_BN), x.omega_BN_B};
}
inline AttitudeState to_mrp(const AttitudeStateQuaternion& x) noexcept {
  return AttitudeState{quat_to_mrp(x.q_BN.canonical()), x.omega_BN_B};  // |σ| ≤ 1
}
inline AttitudeStateEuler123 to_euler123(const AttitudeState& x) noexcept {
  return AttitudeStateEuler123{dcm_to_euler123(mrp_to_dcm(x.sigma_BN)), x.omega_BN_B};
}
inline AttitudeState to_mrp(const AttitudeStateEuler123& x) noexcept {
  return AttitudeState{dcm_to_mrp(euler123_to_dcm(x.theta_BN_rad)), x.omega_BN_B};
}

// ---------------------------------------------------------------------------------------------
// Attitude reference

//! Reference attitude R with its inertial rate and acceleration (Basilisk's attRefMsg).
struct AttitudeReference {
  Vec3 sigma_RN = Vec3::Zero();     //!< [-] reference attitude MRP
  Vec3 omega_RN_N = Vec3::Zero();   //!< [rad/s] reference rate, N components
  Vec3 domega_RN_N = Vec3::Zero();  //!< [rad/s²] reference angular acceleration, N components
};

//! Reference as an MRP and its derivatives (seed 001's form: the law tracks σ̈_d directly).
struct MrpReferenceSample {
  Vec3 sigma = Vec3::Zero();       //!< [-] σ_d (σ_RN)
  Vec3 sigma_dot = Vec3::Zero();   //!< [1/s] σ̇_d
  Vec3 sigma_ddot = Vec3::Zero();  //!< [1/s²] σ̈_d
  Vec3 omega = Vec3::Zero();       //!< [rad/s] ω_f = ω_RN, R components
  Vec3 omega_dot = Vec3::Zero();   //!< [rad/s²] ω̇_f, R components
};

//! Reference as x-y-z Euler angles and their derivatives (seed 002's form).
struct EulerReferenceSample {
  Vec3 angles = Vec3::Zero();       //!< [rad] ϑ_d (x-y-z)
  Vec3 angles_dot = Vec3::Zero();   //!< [rad/s] ϑ̇_d
  Vec3 angles_ddot = Vec3::Zero();  //!< [rad/s²] ϑ̈_d
};

//! MRP-derivative view → inertial-rate view: ω_RN_N = C_RNᵀ ω_f; ω̇ is the same seen from R and
//! from N (ω × ω = 0), so domega_RN_N = C_RNᵀ ω̇_f.
inline AttitudeReference to_attitude_reference(const MrpReferenceSample& r) noexcept {
  const Mat3 C_RN = mrp_to_dcm(r.sigma);
  return AttitudeReference{r.sigma, C_RN.transpose() * r.omega, C_RN.transpose() * r.omega_dot};
}

//! Inertial-rate view → MRP-derivative view: σ̇ = G(σ) ω_R, σ̈ = Ġ(σ, σ̇) ω_R + G(σ) ω̇_R.
inline MrpReferenceSample to_mrp_reference(const AttitudeReference& r) noexcept {
  const Mat3 C_RN = mrp_to_dcm(r.sigma_RN);
  MrpReferenceSample s;
  s.sigma = r.sigma_RN;
  s.omega = C_RN * r.omega_RN_N;
  s.omega_dot = C_RN * r.domega_RN_N;
  s.sigma_dot = mrp_G(s.sigma) * s.omega;
  s.sigma_ddot = mrp_G_dot(s.sigma, s.sigma_dot) * s.omega + mrp_G(s.sigma) * s.omega_dot;
  return s;
}

//! Inertial-rate view → Euler view: ϑ from C_RN, ϑ̇ = F(ϑ) ω_R, ϑ̈ = F(ϑ)(ω̇_R − Ġ(ϑ, ϑ̇) ϑ̇) with
//! ω = G(ϑ) ϑ̇. singular at gimbal lock (|cos ϑ_2| tiny), the output then untouched.
[[nodiscard]] inline Status to_euler_reference(const AttitudeReference& r, EulerReferenceSample& out) noexcept {
  const Mat3 C_RN = mrp_to_dcm(r.sigma_RN);
  const Vec3 angles = dcm_to_euler123(C_RN);
  Mat3 F;
  const Status s = euler123_F(angles, F);
  if (s != Status::ok) return s;
  const Vec3 w = C_RN * r.omega_RN_N, w_dot = C_RN * r.domega_RN_N;
  out.angles = angles;
  out.angles_dot = F * w;
  out.angles_ddot = F * (w_dot - euler123_G_dot(angles, out.angles_dot) * out.angles_dot);
  return Status::ok;
}

// ---------------------------------------------------------------------------------------------
// Commands

//! A torque request on the body (what every attitude torque law outputs).
struct BodyTorque {
  Vec3 torque_B_Nm = Vec3::Zero();  //!< [N m] control torque, B components
};

//! A force and torque request on the body (what the SE(3) laws output); the stacked order
//! [torque; force] is seed 003's u = [M; F].
struct Wrench {
  Vec3 torque_B_Nm = Vec3::Zero();  //!< [N m] control torque, B components
  Vec3 force_B_N = Vec3::Zero();    //!< [N] control force, B components
  Vec6 stacked() const noexcept { return stack3(torque_B_Nm, force_B_N); }
  static Wrench from_stacked(const Vec6& u) noexcept { return Wrench{u.head<3>(), u.tail<3>()}; }
};

//! Motor torques of N reaction wheels about their spin axes.
template <int N>
struct WheelTorques {
  Vec<N> u_s_Nm = Vec<N>::Zero();  //!< [N m] motor torque on each wheel
};

//! Rates of M CMG gimbals and accelerations of N wheels (a VSCMG cluster's input).   seed 001 eq. (12)
template <int M, int N>
struct VscmgRates {
  Vec<M> gamma_dot_rad_s = Vec<M>::Zero();   //!< [rad/s] gimbal rates
  Vec<N> Omega_dot_rad_s2 = Vec<N>::Zero();  //!< [rad/s²] wheel accelerations
  //! [γ̇ (M); Ω̇_w (N)], the plant's input order.
  Vec<M + N> stacked() const noexcept {
    Vec<M + N> u;
    u.template head<M>() = gamma_dot_rad_s;
    u.template tail<N>() = Omega_dot_rad_s2;
    return u;
  }
  static VscmgRates from_stacked(const Vec<M + N>& u) noexcept {
    return VscmgRates{u.template head<M>(), u.template tail<N>()};
  }
};

// ---------------------------------------------------------------------------------------------
// Actuator and sensor samples

//! State of a VSCMG cluster as measured: gimbal angles and wheel speeds.
template <int M, int N>
struct VscmgState {
  Vec<M> gamma_rad = Vec<M>::Zero();    //!< [rad] gimbal angles
  Vec<N> Omega_rad_s = Vec<N>::Zero();  //!< [rad/s] wheel speeds relative to the body
};

//! A rate-gyro sample.
struct GyroSample {
  double t_s = 0.0;                //!< [s] sample time
  Vec3 omega_BN_B = Vec3::Zero();  //!< [rad/s] measured body rate
  bool valid = true;               //!< false: no sample this period (dropout)
};

//! A star-tracker sample.
struct StarTrackerSample {
  double t_s = 0.0;                              //!< [s] sample time
  QuaternionSF q_BN = QuaternionSF::identity();  //!< [-] measured attitude
  bool valid = true;                             //!< false: no solution this period
};

//! K accelerometer axes (seed 004's saturated electrostatic accelerometers).
template <int K>
struct AccelerometerSample {
  double t_s = 0.0;                  //!< [s] sample time
  Vec<K> a_m_s2 = Vec<K>::Zero();    //!< [m/s²] readings (possibly at the range limit)
};

}  // namespace adcs
