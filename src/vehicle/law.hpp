#pragma once
// The torque law a vehicle file chooses, as one component (core/component.hpp) for the loop:
// MrpPd<N> (N: the wheels in its gyroscopic term) or seed 002's PPC law through the Euler view
// (vehicle/ppc_law.hpp). One type for both, so each actuator set instantiates the closed loop once,
// not once per law (compile time). Both read the same measured state and inertial reference.
#include <variant>

#include "adcs/control/mrp_pd.hpp"
#include "adcs/core/component.hpp"
#include "adcs/core/signals.hpp"
#include "vehicle/config.hpp"
#include "vehicle/ppc_law.hpp"

namespace adcs::sim::vehicle {

template <int N>
struct VehicleLawInput {
  double t_s = 0.0;                     //!< [s] since the start of the run
  AttitudeState state{};                //!< measured σ_BN, ω_BN_B
  Vec<N> Omega_rad_s = Vec<N>::Zero();  //!< [rad/s] wheel speeds (MRP PD's gyroscopic term)
  AttitudeReference reference{};
};

struct VehicleLawDiagnostics {
  bool funnel_reopened = false;  //!< PPC: this step re-opened the funnel
};

template <int N>
class VehicleLaw {
 public:
  using Params = std::variant<MrpPdParams<N>, PpcNeuralParams>;
  using Input = VehicleLawInput<N>;
  using Output = BodyTorque;
  using Diagnostics = VehicleLawDiagnostics;

  explicit VehicleLaw(const Params& p) noexcept : law_(make(p)) {}

  Status status() const noexcept {
    return std::visit([](const auto& l) { return l.status(); }, law_);
  }
  void reset() noexcept {
    std::visit([](auto& l) { l.reset(); }, law_);
  }
  double period_s() const noexcept {
    return std::visit([](const auto& l) { return l.period_s(); }, law_);
  }
  //! PPC funnel re-openings (0 for MRP PD).
  long funnel_recoveries() const noexcept {
    const PpcEulerLaw* p = std::get_if<PpcEulerLaw>(&law_);
    return p ? p->funnel_recoveries() : 0;
  }

  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    if (diag) *diag = Diagnostics{};
    if (MrpPd<N>* pd = std::get_if<MrpPd<N>>(&law_))
      return pd->step(typename MrpPd<N>::Input{in.state, in.Omega_rad_s, in.reference}, out);
    bool reopened = false;
    const Status s = std::get_if<PpcEulerLaw>(&law_)->step(in.t_s, in.state, in.reference, out, reopened);
    if (diag) diag->funnel_reopened = reopened;
    return s;
  }

 private:
  using Law = std::variant<MrpPd<N>, PpcEulerLaw>;
  static Law make(const Params& p) noexcept {
    if (const MrpPdParams<N>* pd = std::get_if<MrpPdParams<N>>(&p)) return Law(std::in_place_type<MrpPd<N>>, *pd);
    return Law(std::in_place_type<PpcEulerLaw>, *std::get_if<PpcNeuralParams>(&p));
  }
  Law law_;
};

//! The law's parameters from the file: MRP PD with the wheels' (believed) J_rw = J − Σ J_s g gᵀ,
//! axes and spin inertias; PPC with the believed total inertia J. Period: the control period.
template <int N>
typename VehicleLaw<N>::Params make_law_params(const ControllerConfig& c, double period_s, const Mat3& J_kgm2,
                                               const Mat3& J_rw_kgm2, const Mat<3, N>& G_s_B, const Vec<N>& J_s_kgm2) {
  if (!c.ppc) {
    MrpPdParams<N> p;
    p.K = c.K_Nm;
    p.P = c.P_Nms.asDiagonal();
    p.J_rw_B = J_rw_kgm2;
    p.G_s_B = G_s_B;
    p.J_s = J_s_kgm2;
    p.period_s = period_s;
    p.on_failure = c.on_failure;
    return p;
  }
  PpcNeuralParams p;
  p.gains.J = J_kgm2;
  p.gains.lambda = c.lambda;
  p.gains.K = c.K;
  p.gains.compensator.tau_w = c.tau_w;
  p.gains.compensator.tau_mu = c.tau_mu;
  p.gains.compensator.beta = c.beta;
  p.gains.compensator.gamma = c.gamma;
  p.gains.compensator.sigma = c.sigma;
  p.gains.period_s = period_s;
  p.gains.on_failure = c.on_failure;
  p.ppc = c.funnel;
  return p;
}

}  // namespace adcs::sim::vehicle
