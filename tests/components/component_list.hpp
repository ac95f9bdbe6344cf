#pragma once
// The one list of flight components (issue 17), free of any test framework, and, per component, what a typed test needs to run
// it: a valid Params, a valid Input that varies with the sample index k, and a way to poison an
// Input (a NaN where the component must notice it). Every suite written over FlightComponents
// (the component contract, no-allocation) covers a component as soon as it is added here:
//
//   template <> struct ComponentFixture<MyLaw> {
//     static MyLaw::Params params();
//     static MyLaw::Input input(int k);
//     static void poison(MyLaw::Input& in);
//   };
//   ... and MyLaw in FlightComponents below.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <tuple>
#include <string>

#include "adcs/adcs.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace adcs::test {

template <class C>
struct ComponentFixture;

//! Whether every rejected step (status not usable) leaves the component's state untouched. True
//! for laws and actuation stages; an estimator whose measurement is rejected keeps its prediction
//! (it coasts, core/component.hpp), so only its rejected time update leaves the state as it was.
template <class C>
inline constexpr bool kRejectionKeepsState = true;

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

//! A fixture's set-up call that cannot fail on its fixed data; abort loudly if it ever does.
inline void require(Status s) {
  if (s != Status::ok) std::abort();
}

inline Mat<3, 4> four_wheel_axes() {
  Mat<3, 4> G;
  const double s = 1.0 / std::sqrt(3.0);
  G << 1, 0, 0, s, 0, 1, 0, s, 0, 0, 1, s;
  return G;
}

// ---- controllers -------------------------------------------------------------------------------

template <>
struct ComponentFixture<MrpPd<4>> {
  static constexpr const char* name = "MrpPd4";
  static MrpPd<4>::Params params() {
    MrpPd<4>::Params p;
    p.K = 3.0;
    p.P = 40.0 * Mat3::Identity();
    p.J_rw_B = Vec3(900, 800, 600).asDiagonal();
    p.G_s_B = four_wheel_axes();
    p.J_s.setConstant(0.1);
    p.period_s = 0.1;
    return p;
  }
  static MrpPd<4>::Input input(int k) {
    MrpPd<4>::Input in;
    in.state.sigma_BN = Vec3(0.1 + 1e-3 * k, -0.2, 0.3);
    in.state.omega_BN_B = Vec3(0.01, 0.0, -0.02);
    in.Omega_rad_s << 10, 20, 30, 40;
    in.reference.sigma_RN = Vec3(0.0, 0.1, 0.0);
    in.reference.omega_RN_N = Vec3(0.0, 0.0, 1e-3);
    return in;
  }
  static void poison(MrpPd<4>::Input& in) { in.state.omega_BN_B(1) = kNaN; }
};

template <>
struct ComponentFixture<HybridAdaptive<4, 3>> {
  static constexpr const char* name = "HybridAdaptive43";
  using C = HybridAdaptive<4, 3>;
  static C::Params params() {
    C::Params p;
    p.nominal = pyramid_4cmg_3rw_nominal();
    return p;
  }
  static C::Input input(int k) {
    C::Input in;
    in.state.sigma_BN = Vec3(0.01, -0.02, 0.03);
    in.state.omega_BN_B = Vec3(1e-3, 2e-3, -1e-3);
    in.actuators.gamma_rad(0) = 1e-3 * k;
    in.reference = SinusoidalRateReference().sample(1e-3 * k, 0.5 * in.state.sigma_BN);
    return in;
  }
  static void poison(C::Input& in) { in.state.omega_BN_B(2) = kNaN; }
};

inline EulerTrackingInput euler_tracking_input(int k) {
  EulerTrackingInput in;
  in.t_s = 1e-4 * k;
  in.state.theta_BN_rad = Vec3(0.002, -0.001, 0.003);
  in.state.omega_BN_B = Vec3(1e-4, -2e-4, 1e-4);
  in.reference = SinusoidalEulerReference().sample(in.t_s);
  return in;
}

template <>
struct ComponentFixture<PpcNeural> {
  static constexpr const char* name = "PpcNeural";
  static PpcNeural::Params params() {
    PpcNeural::Params p;
    p.gains = seed002_tracking_gains();
    return p;
  }
  static PpcNeural::Input input(int k) { return euler_tracking_input(k); }
  static void poison(PpcNeural::Input& in) { in.state.omega_BN_B(0) = kNaN; }
};

template <>
struct ComponentFixture<AdaptiveTracking> {
  static constexpr const char* name = "AdaptiveTracking";
  static AdaptiveTracking::Params params() { return AdaptiveTracking::Params{seed002_tracking_gains()}; }
  static AdaptiveTracking::Input input(int k) { return euler_tracking_input(k); }
  static void poison(AdaptiveTracking::Input& in) { in.reference.angles_ddot(2) = kNaN; }
};

template <>
struct ComponentFixture<EsoAdrcAttitude> {
  static constexpr const char* name = "EsoAdrcAttitude";
  static EsoAdrcAttitude::Params params() {
    EsoAdrcAttitude::Params p;
    p.J_B_kgm2 = flexible_params_seed002().J;
    p.omega_o_rad_s = 2.0;
    p.omega_c_rad_s = 0.5;
    p.period_s = 0.05;
    return p;
  }
  static EsoAdrcAttitude::Input input(int k) { return euler_tracking_input(k); }
  static void poison(EsoAdrcAttitude::Input& in) { in.state.theta_BN_rad(1) = kNaN; }  // the law reads only angles
};

inline Se3SpacecraftParams se3_nominal_chaser() {
  Se3SpacecraftParams p;
  p.J_B << 25, 1, 0.5, 1, 22, 1.2, 0.5, 1.2, 23;
  p.m = 105.0;
  return p;
}

inline Se3TrackingInput se3_tracking_input(int k) {
  Se3TrackingInput in;
  in.state.R_N = Vec3(7.0e6, 10.0 + 0.01 * k, -5.0);
  in.state.v_B = Vec3(0.0, 7.5e3, 0.1);
  in.state.omega_BN_B = Vec3(1e-3, -2e-3, 1e-3);
  in.state.C_NB = Eigen::AngleAxisd(0.05, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  in.desired.R_N = Vec3(7.0e6, 0.0, 0.0);
  in.desired.v_D = Vec3(0.0, 7.5e3, 0.0);
  in.desired.omega_DN_D = Vec3(0.0, 0.0, 1.1e-3);
  return in;
}

template <>
struct ComponentFixture<PrescribedTimeSe3> {
  static constexpr const char* name = "PrescribedTimeSe3";
  static PrescribedTimeSe3::Params params() {
    PrescribedTimeSe3::Params p;
    p.nominal = se3_nominal_chaser();
    p.zeta = quantization_compensation_gain(seed003_quantizer_params());
    return p;
  }
  static PrescribedTimeSe3::Input input(int k) { return se3_tracking_input(k); }
  static void poison(PrescribedTimeSe3::Input& in) { in.state.v_B(0) = kNaN; }
};

template <>
struct ComponentFixture<FtsmcSe3> {
  static constexpr const char* name = "FtsmcSe3";
  static FtsmcSe3::Params params() {
    FtsmcSe3::Params p;
    p.nominal = se3_nominal_chaser();
    return p;
  }
  static FtsmcSe3::Input input(int k) { return se3_tracking_input(k); }
  static void poison(FtsmcSe3::Input& in) { in.desired.omega_dot_D(1) = kNaN; }
};

template <>
struct ComponentFixture<DragFreeAdrc> {
  static constexpr const char* name = "DragFreeAdrc";
  static DragFreeAdrc::Params params() { return DragFreeAdrc::Params{}; }  // seed 004's configuration
  static DragFreeAdrc::Input input(int k) {
    DragFreeAdrc::Input in;
    for (int i = 0; i < 27; ++i) in.x_hat(i) = 1e-7 * std::sin(0.3 * i + 0.1 * k);
    in.F_D_hat_N = Vec3(1e-6, -2e-6, 5e-7);
    in.phi_sc_cmd_rad = Vec3(1e-5, 0.0, -1e-5);
    return in;
  }
  static void poison(DragFreeAdrc::Input& in) { in.x_hat(DragFreeIndex::r) = kNaN; }
};

template <>
struct ComponentFixture<Pid<3>> {
  static constexpr const char* name = "Pid3";
  static Pid<3>::Params params() {
    Pid<3>::Params p;
    p.kp = Vec3(5.55, 5.55, 5.55);
    p.ki = Vec3(0.1, 0.1, 0.1);
    p.kd = Vec3(9.0, 9.0, 9.0);
    return p;
  }
  static Pid<3>::Input input(int k) { return Pid<3>::Input{Vec3(1e-6 * k, -2e-6, 3e-6), Vec3(1e-7, 0.0, -1e-7)}; }
  static void poison(Pid<3>::Input& in) { in.e_d(1) = kNaN; }
};

// ---- estimators --------------------------------------------------------------------------------

template <>
struct ComponentFixture<DragFreeEskf> {
  static constexpr const char* name = "DragFreeEskf";
  static DragFreeEskf::Params params() {
    const DragFreeParams pl;
    DragFreeDiscrete d;
    require(drag_free_discretize(pl, d));
    const DragFreeNoise n = drag_free_noise(pl);
    DragFreeEskf::Params e;
    e.A_d = d.A_d;
    e.B_d = d.B_d;
    e.B_e = d.B_e;
    e.C_d = d.C_d;
    const double q = std::pow(7.7e-3 * 1.2e-3 * pl.period_s, 2);  // spec §B.8, as dragfree-adrc
    e.q << Vec3::Constant(q), Vec3::Constant(q), Vec3::Zero();
    Vec<9> s;
    s << Vec3::Constant(n.sigma_T_sc * n.sigma_T_sc), Vec3::Constant(n.sigma_F_sc * n.sigma_F_sc),
        Vec3::Constant(n.sigma_T_tm * n.sigma_T_tm);
    e.S = s.asDiagonal();
    e.R = n.sigma_pos * n.sigma_pos * Mat<9, 9>::Identity();
    e.period_s = pl.period_s;
    return e;
  }
  static DragFreeEskf::Input input(int k) {
    DragFreeEskf::Input in;
    for (int i = 0; i < 9; ++i) in.y(i) = 1e-8 * std::cos(0.2 * i + 0.1 * k);
    in.u(3) = 1e-4;
    return in;
  }
  static void poison(DragFreeEskf::Input& in) { in.u(0) = kNaN; }
};

template <>
struct ComponentFixture<SaturatedEsf> {
  static constexpr const char* name = "SaturatedEsf";
  static SaturatedEsf::Params params() {
    const DragFreeParams pl;
    DragFreeAxisModel m;
    require(drag_free_axis_model(pl, 0, m));
    SaturatedEsf::Params e;
    e.A_d = m.A_d;
    e.B_d = m.B_d;
    e.C = m.C;
    e.D = m.D;
    e.q = std::pow(7.7e-3 * 1.2e-3 * pl.period_s, 2);
    e.R_a = std::pow(drag_free_noise(pl).sigma_acc, 2);
    e.y_min = pl.accel_min;
    e.y_max = pl.accel_max;
    e.period_s = pl.period_s;
    return e;
  }
  static SaturatedEsf::Input input(int k) {
    SaturatedEsf::Input in;
    in.y_c_m_s2 = 1e-7 * std::sin(0.1 * k);
    in.u = in.u_prev = 1e-4;
    return in;
  }
  static void poison(SaturatedEsf::Input& in) { in.u_prev = kNaN; }
};

template <>
inline constexpr bool kRejectionKeepsState<DragFreeEskf> = false;
template <>
inline constexpr bool kRejectionKeepsState<SaturatedEsf> = false;

// ---- actuation ---------------------------------------------------------------------------------

template <>
struct ComponentFixture<RwTorqueAllocator<4>> {
  static constexpr const char* name = "RwTorqueAllocator4";
  static RwTorqueAllocator<4>::Params params() {
    RwTorqueAllocator<4>::Params p;
    p.G_s_B = four_wheel_axes();
    return p;
  }
  static RwTorqueAllocator<4>::Input input(int k) { return BodyTorque{Vec3(0.01 * k, -0.05, 0.02)}; }
  static void poison(RwTorqueAllocator<4>::Input& in) { in.torque_B_Nm(0) = kNaN; }
};

// ---- float instances (issue 19): the double fixture's data, rounded once ----------------------

inline constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();

template <>
struct ComponentFixture<MrpPd<4, float>> {
  static constexpr const char* name = "MrpPd4f";
  using C = MrpPd<4, float>;
  using D = ComponentFixture<MrpPd<4>>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) { return D::input(k).cast<float>(); }
  static void poison(C::Input& in) { in.state.omega_BN_B(1) = kNaNf; }
};

template <>
struct ComponentFixture<RwTorqueAllocator<4, float>> {
  static constexpr const char* name = "RwTorqueAllocator4f";
  using C = RwTorqueAllocator<4, float>;
  using D = ComponentFixture<RwTorqueAllocator<4>>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) { return D::input(k).cast<float>(); }
  static void poison(C::Input& in) { in.torque_B_Nm(0) = kNaNf; }
};

template <>
struct ComponentFixture<PpcNeuralT<float>> {
  static constexpr const char* name = "PpcNeuralf";
  using C = PpcNeuralT<float>;
  using D = ComponentFixture<PpcNeural>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) { return D::input(k).cast<float>(); }
  static void poison(C::Input& in) { in.state.omega_BN_B(0) = kNaNf; }
};

template <>
struct ComponentFixture<HybridAdaptive<4, 3, float>> {
  static constexpr const char* name = "HybridAdaptive43f";
  using C = HybridAdaptive<4, 3, float>;
  using D = ComponentFixture<HybridAdaptive<4, 3>>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) { return D::input(k).cast<float>(); }
  static void poison(C::Input& in) { in.state.omega_BN_B(2) = kNaNf; }
};

template <>
struct ComponentFixture<AdaptiveTrackingT<float>> {
  static constexpr const char* name = "AdaptiveTrackingf";
  using C = AdaptiveTrackingT<float>;
  using D = ComponentFixture<AdaptiveTracking>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) { return D::input(k).cast<float>(); }
  static void poison(C::Input& in) { in.reference.angles_ddot(2) = kNaNf; }
};

template <>
struct ComponentFixture<EsoAdrcAttitudeT<float>> {
  static constexpr const char* name = "EsoAdrcAttitudef";
  using C = EsoAdrcAttitudeT<float>;
  using D = ComponentFixture<EsoAdrcAttitude>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) { return D::input(k).cast<float>(); }
  static void poison(C::Input& in) { in.state.theta_BN_rad(1) = kNaNf; }  // the law reads only angles
};

template <>
struct ComponentFixture<PrescribedTimeSe3T<float>> {
  static constexpr const char* name = "PrescribedTimeSe3f";
  using C = PrescribedTimeSe3T<float>;
  using D = ComponentFixture<PrescribedTimeSe3>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) { return D::input(k).cast<float>(); }
  static void poison(C::Input& in) { in.state.v_B(0) = kNaNf; }
};

template <>
struct ComponentFixture<FtsmcSe3T<float>> {
  static constexpr const char* name = "FtsmcSe3f";
  using C = FtsmcSe3T<float>;
  using D = ComponentFixture<FtsmcSe3>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) { return D::input(k).cast<float>(); }
  static void poison(C::Input& in) { in.desired.omega_dot_D(1) = kNaNf; }
};

template <>
struct ComponentFixture<Saturation<6>> {
  static constexpr const char* name = "Saturation6";
  static Saturation<6>::Params params() { return Saturation<6>::Params{Vec6(0.5, 0.5, 0.5, 5, 5, 5)}; }
  static Saturation<6>::Input input(int k) { return Vec6(0.1 * k, -0.2, 0.3, 1.0, -7.0, 0.0); }
  static void poison(Saturation<6>::Input& in) { in(4) = kNaN; }
};

template <>
struct ComponentFixture<SaturatedQuantizer<6>> {
  static constexpr const char* name = "SaturatedQuantizer6";
  static SaturatedQuantizer<6>::Params params() {
    return SaturatedQuantizer<6>::Params{seed003_quantizer_params(), Vec6(0.5, 0.5, 0.5, 5, 5, 5)};
  }
  static SaturatedQuantizer<6>::Input input(int k) { return Vec6(0.01 * k, -0.2, 0.3, 1.0, -7.0, 0.0); }
  static void poison(SaturatedQuantizer<6>::Input& in) { in(2) = kNaN; }
};

template <>
struct ComponentFixture<Saturation<6, float>> {
  static constexpr const char* name = "Saturation6f";
  using C = Saturation<6, float>;
  using D = ComponentFixture<Saturation<6>>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) { return D::input(k).cast<float>(); }
  static void poison(C::Input& in) { in(4) = std::numeric_limits<float>::quiet_NaN(); }
};

template <>
struct ComponentFixture<SaturatedQuantizer<6, float>> {
  static constexpr const char* name = "SaturatedQuantizer6f";
  using C = SaturatedQuantizer<6, float>;
  using D = ComponentFixture<SaturatedQuantizer<6>>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) { return D::input(k).cast<float>(); }
  static void poison(C::Input& in) { in(2) = std::numeric_limits<float>::quiet_NaN(); }
};

template <>
struct ComponentFixture<DragFreeEskfT<float>> {
  static constexpr const char* name = "DragFreeEskff";
  using C = DragFreeEskfT<float>;
  using D = ComponentFixture<DragFreeEskf>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) {
    const DragFreeEskf::Input d = D::input(k);
    C::Input in;
    in.u = d.u.cast<float>();
    in.delta_f_nominal = d.delta_f_nominal.cast<float>();
    in.y = d.y.cast<float>();
    return in;
  }
  static void poison(C::Input& in) { in.u(0) = kNaNf; }
};
template <>
inline constexpr bool kRejectionKeepsState<DragFreeEskfT<float>> = false;

template <>
struct ComponentFixture<SaturatedEsfT<float>> {
  static constexpr const char* name = "SaturatedEsff";
  using C = SaturatedEsfT<float>;
  using D = ComponentFixture<SaturatedEsf>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) {
    const SaturatedEsf::Input d = D::input(k);
    return C::Input{narrow_scalar<float>(d.u_prev), narrow_scalar<float>(d.delta_f_nominal),
                    narrow_scalar<float>(d.y_c_m_s2), narrow_scalar<float>(d.u)};
  }
  static void poison(C::Input& in) { in.u_prev = kNaNf; }
};
template <>
inline constexpr bool kRejectionKeepsState<SaturatedEsfT<float>> = false;

template <>
struct ComponentFixture<DragFreeAdrcT<float>> {
  static constexpr const char* name = "DragFreeAdrcf";
  using C = DragFreeAdrcT<float>;
  using D = ComponentFixture<DragFreeAdrc>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) {
    const DragFreeAdrc::Input d = D::input(k);
    C::Input in;
    in.x_hat = scalar_cast<float>(d.x_hat);
    in.F_D_hat_N = scalar_cast<float>(d.F_D_hat_N);
    in.phi_sc_cmd_rad = scalar_cast<float>(d.phi_sc_cmd_rad);
    return in;
  }
  static void poison(C::Input& in) { in.x_hat(DragFreeIndex::r) = kNaNf; }
};

template <>
struct ComponentFixture<Pid<3, float>> {
  static constexpr const char* name = "Pid3f";
  using C = Pid<3, float>;
  using D = ComponentFixture<Pid<3>>;
  static C::Params params() { return D::params().cast<float>(); }
  static C::Input input(int k) {
    const Pid<3>::Input d = D::input(k);
    return C::Input{scalar_cast<float>(d.e_p), scalar_cast<float>(d.e_d)};
  }
  static void poison(C::Input& in) { in.e_d(1) = kNaNf; }
};

template <>
struct ComponentFixture<VscmgSteering<4, 0>> {
  static constexpr const char* name = "VscmgSteering40";
  using C = VscmgSteering<4, 0>;
  static C::Params params() {
    C::Params p;
    require(set_cmg_pyramid(54.74 * kPiRad / 180.0, 0.03, p.geometry));
    return p;
  }
  static C::Input input(int k) {
    C::Input in;
    in.t_s = 0.1 * k;
    in.request.torque_B_Nm = Vec3(1e-3, -2e-3, 5e-4);
    in.actuators.gamma_rad = Vec<4>(0.1 * k, -0.2, 0.3, 0.05);
    return in;
  }
  static void poison(C::Input& in) { in.actuators.gamma_rad(3) = kNaN; }
};

// ---- the numbers of an output (finiteness and bit comparisons; no heap) ------------------------

//! Up to kMaxOutputValues numbers of any component's Output, written to `dst`; returns the count.
inline constexpr int kMaxOutputValues = 32;
template <class Derived>
int put_values(const Eigen::MatrixBase<Derived>& x, double* dst) {
  for (Eigen::Index i = 0; i < x.size(); ++i) dst[i] = x.derived().coeff(i);
  return static_cast<int>(x.size());
}
template <class S>
int output_values(const BodyTorqueT<S>& o, double* d) { return put_values(o.torque_B_Nm, d); }
template <class S>
int output_values(const WrenchT<S>& o, double* d) { return put_values(o.stacked(), d); }
template <int M, int N, class S>
int output_values(const VscmgRates<M, N, S>& o, double* d) { return put_values(o.stacked(), d); }
template <int N, class S>
int output_values(const WheelTorques<N, S>& o, double* d) { return put_values(o.u_s_Nm, d); }
template <int N, class S>
int output_values(const PidOutput<N, S>& o, double* d) { return put_values(o.u, d); }
template <int N, class S>
int output_values(const EskfOutput<N, S>& o, double* d) { return put_values(o.x_hat, d); }
template <class S>
int output_values(const SaturatedEsfOutputT<S>& o, double* d) { return put_values(o.x_hat, d); }
template <class S>
int output_values(const DragFreeActuationT<S>& o, double* d) { return put_values(o.stacked(), d); }
template <int L, class S>
int output_values(const Vec<L, S>& o, double* d) { return put_values(o, d); }

//! The numbers of an output, by value (fixed capacity, count n).
struct OutputValues {
  double v[kMaxOutputValues] = {};
  int n = 0;
  template <class Out>
  explicit OutputValues(const Out& o) : n(output_values(o, v)) {}
  bool finite() const {
    for (int i = 0; i < n; ++i)
      if (!std::isfinite(v[i])) return false;
    return true;
  }
  //! Bit-identical (NaN payloads and the sign of zero included).
  bool same_bits(const OutputValues& o) const {
    return n == o.n && std::memcmp(v, o.v, sizeof(double) * static_cast<std::size_t>(n)) == 0;
  }
};

//! Every flight component. Add a component here (with its ComponentFixture) and every suite written
//! over the list covers it: the typed gtest suites (component_fixtures.hpp: ComponentContract,
//! NoMallocComponent), the benchmarks (bench: BM_Component_<name>_Step) and the fuzzer
//! (tests/fuzz/fuzz_components.cpp).
using FlightComponentList = std::tuple<MrpPd<4>, HybridAdaptive<4, 3>, PpcNeural, AdaptiveTracking, PrescribedTimeSe3, FtsmcSe3,
                     DragFreeAdrc, Pid<3>, DragFreeEskf, SaturatedEsf, RwTorqueAllocator<4>, Saturation<6>,
                     SaturatedQuantizer<6>, VscmgSteering<4, 0>, EsoAdrcAttitude, MrpPd<4, float>,
                     RwTorqueAllocator<4, float>, PpcNeuralT<float>, HybridAdaptive<4, 3, float>,
                     AdaptiveTrackingT<float>, EsoAdrcAttitudeT<float>, PrescribedTimeSe3T<float>,
                     FtsmcSe3T<float>, Saturation<6, float>, SaturatedQuantizer<6, float>, DragFreeEskfT<float>,
                     SaturatedEsfT<float>, DragFreeAdrcT<float>, Pid<3, float>>;

//! Calls f(static_cast<C*>(nullptr)) for every component type C of the list, in order
//! (components are not default constructible, so the type travels as a null pointer).
template <class F, class... C>
void for_each_component_in(std::tuple<C...>*, F&& f) {
  (f(static_cast<C*>(nullptr)), ...);
}
template <class F>
void for_each_component(F&& f) {
  for_each_component_in(static_cast<FlightComponentList*>(nullptr), f);
}

}  // namespace adcs::test
