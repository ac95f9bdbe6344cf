#pragma once
// Replay core of the rigid-wheel attitude chain (issue 19): MrpPd<4, S> + RwTorqueAllocator<4, S>
// on the 12U cubesat of examples/cubesat_mrp_pd.cpp (J = diag(0.20, 0.25, 0.15) kg m^2, four
// wheels in a 30 deg pyramid, J_s = 2e-5 kg m^2, 3 mN m per wheel; critically damped axes at
// w_n = 0.1 rad/s, 10 Hz), through its 30 deg slew about (1, 2, 3)/sqrt(14). S = double is the
// Cortex-M7 System "attitude", S = float the Cortex-M4F System "attitude_f" (single-precision
// FPU). One step() = three stages: the recorded row (doubles) converted to the law's scalar, the
// law's step() and the allocation's step(), so that the cost of each flight call is measured
// without the driver's conversion (on the M4F a double-to-float conversion is a library call).
#include <cmath>
#include <type_traits>

#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "adcs/plant/vscmg_configurations.hpp"  // wheel_pyramid_axes()
#include "replay_system.hpp"

namespace replay {

template <class S>
class AttitudeSystem {
 public:
  using Law = adcs::MrpPd<4, S>;
  using Allocator = adcs::RwTorqueAllocator<4, S>;
  static constexpr const char* kName = std::is_same_v<S, float> ? "attitude_f" : "attitude";
  // Row: σ_BN (3), ω_BN_B (3), Ω (4), σ_RN (3).
  static constexpr int kInputWidth = 13;
  static constexpr int kCommandSize = 4, kParts = 1;
  static constexpr double kPeriod = 0.1;  // [s] 10 Hz, as examples/cubesat_mrp_pd.cpp
  // Comparison scales (replay_system.hpp, Column): the torques reach 0.3 .. 3 mN m in the slew.
  static constexpr double kTorque = 1e-4;
  static constexpr Column kColumns[] = {{"status_law", 0.0}, {"status_alloc", 0.0}, {"L1", kTorque},
                                        {"L2", kTorque},     {"L3", kTorque},       {"u1", kTorque},
                                        {"u2", kTorque},     {"u3", kTorque},       {"u4", kTorque}};
  static constexpr int kCostStages = 3;
  static constexpr const char* kStageNames[kCostStages] = {"inputs", "mrp_pd_step", "rw_allocation_step"};

  //! The cubesat's law and allocation, computed in double and converted once (cast<S>()).
  static adcs::MrpPdParams<4> law_params_double() noexcept {
    constexpr double kDeg = adcs::kPiRad / 180.0, w_n = 0.1;
    adcs::MrpPdParams<4> p;
    const adcs::Vec3 J(0.20, 0.25, 0.15);
    if (adcs::wheel_pyramid_axes<4>(30.0 * kDeg, p.G_s_B) != adcs::Status::ok) return p;  // NaN: refused
    p.J_s = adcs::Vec<4>::Constant(2e-5);
    p.J_rw_B = adcs::Mat3(J.asDiagonal()) - p.G_s_B * p.J_s.asDiagonal() * p.G_s_B.transpose();
    p.K = 4.0 * 0.25 * w_n * w_n;  // near the target sigma ~ phi/4: K = 4 J_max w_n^2
    p.P = (2.0 * w_n * J).asDiagonal();  // P_i = 2 J_i w_n
    p.period_s = kPeriod;
    return p;
  }
  static typename Law::Params law_params() noexcept { return law_params_double().template cast<S>(); }
  static typename Allocator::Params allocation_params() noexcept {
    adcs::RwAllocationParams<4> a;
    a.G_s_B = law_params_double().G_s_B;
    a.torque_limit = 3e-3;  // [N m]
    return a.template cast<S>();
  }

  AttitudeSystem() noexcept : law_(law_params()), allocator_(allocation_params()) {}
  adcs::Status init_status() const noexcept {
    return law_.status() != adcs::Status::ok ? law_.status() : allocator_.status();
  }

  void step(const double* row) noexcept { step_stages(kCostStages, row); }
  //! The first n stages of step() (cost mode); the law's input and output are members, so that
  //! no stage alone is dead code.
  void step_stages(int n, const double* row) noexcept {
    for (int i = 0; i < 3; ++i) {
      in_.state.sigma_BN(i) = static_cast<S>(row[i]);
      in_.state.omega_BN_B(i) = static_cast<S>(row[3 + i]);
      in_.reference.sigma_RN(i) = static_cast<S>(row[10 + i]);
    }
    for (int j = 0; j < 4; ++j) in_.Omega_rad_s(j) = static_cast<S>(row[6 + j]);
    if (n < 2) return;
    status_law_ = law_.step(in_, torque_);
    if (n < 3) return;
    status_alloc_ = allocator_.step(torque_, wheels_);  // a failed law step commands zero torque
  }

  void step_part(int, const double* row) noexcept { step(row); }
  void command(double* u) const noexcept {
    for (int j = 0; j < 4; ++j) u[j] = static_cast<double>(wheels_.u_s_Nm(j));
  }
  void outputs(double* v) const noexcept {
    *v++ = static_cast<double>(status_law_);
    *v++ = static_cast<double>(status_alloc_);
    for (int i = 0; i < 3; ++i) *v++ = static_cast<double>(torque_.torque_B_Nm(i));
    for (int j = 0; j < 4; ++j) *v++ = static_cast<double>(wheels_.u_s_Nm(j));
  }

 private:
  Law law_;
  Allocator allocator_;
  typename Law::Input in_{};
  adcs::BodyTorqueT<S> torque_{};
  adcs::WheelTorques<4, S> wheels_{};
  adcs::Status status_law_ = adcs::Status::ok, status_alloc_ = adcs::Status::ok;
};

}  // namespace replay
