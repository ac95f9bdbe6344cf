// Seed 002's C family (include/adcs/c/adcs.h: adcs_ppc, adcs_ppcf), shared by its two units:
// adcs_c_ppc.cpp (double) and adcs_c_ppc_f.cpp (float), PpcNeuralT<S>, the prescribed-performance
// adaptive RBF law. One unit per scalar so that a flight build compiles only the precision it
// links (a Cortex-M4F build the float family). Private to src/c.
#pragma once

#include "adcs/c/adcs.h"
#include "adcs/control/ppc_neural.hpp"
#include "c_api_common.hpp"

namespace adcs::c_api {

static_assert(ADCS_ANGLE_UNITS_RADIANS == static_cast<int>(AngleUnits::radians), "units ABI");
static_assert(ADCS_ANGLE_UNITS_DEGREES == static_cast<int>(AngleUnits::degrees), "units ABI");
static_assert(ADCS_FUNNEL_NONE == static_cast<int>(FunnelRecovery::none), "recovery ABI");
static_assert(ADCS_FUNNEL_REOPEN == static_cast<int>(FunnelRecovery::reopen), "recovery ABI");

template <class S, class CParams, class CState>
adcs_status ppc_init(const CParams* cp, CState* state) noexcept {
  if (cp == nullptr || state == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  PpcNeuralParamsT<S> p;
  EulerTrackingGainsT<S>& g = p.gains;
  g.J = from_rows(cp->J_kgm2);
  g.lambda = from_array(cp->lambda);
  g.K = from_array(cp->K);
  g.compensator.layer.centers = from_rows(cp->rbf_centers);
  g.compensator.layer.widths = from_array(cp->rbf_widths);
  g.compensator.tau_w = from_array(cp->tau_w);
  g.compensator.tau_mu = cp->tau_mu;
  g.compensator.beta = cp->beta;
  g.compensator.gamma = cp->gamma;
  g.compensator.sigma = cp->sigma;
  g.period_s = cp->period_s;
  for (int i = 0; i < 3; ++i) p.ppc.rho[i] = PerformanceFunctionT<S>{cp->rho0_rad[i], cp->rho_inf_rad[i], cp->k_rho[i]};
  p.ppc.delta = from_array(cp->delta);
  p.ppc.robust_clamp = cp->robust_clamp != 0;
  // Out-of-range enumerations refuse the set (as a NaN gain does), never an invalid enum.
  if (cp->units == ADCS_ANGLE_UNITS_RADIANS || cp->units == ADCS_ANGLE_UNITS_DEGREES)
    g.units = static_cast<AngleUnits>(cp->units);
  else
    g.period_s = unset_v<S>;
  if (cp->funnel_recovery == ADCS_FUNNEL_NONE || cp->funnel_recovery == ADCS_FUNNEL_REOPEN)
    p.ppc.recovery = static_cast<FunnelRecovery>(cp->funnel_recovery);
  else
    g.period_s = unset_v<S>;
  if (!policy(cp->on_failure, g.on_failure)) g.period_s = unset_v<S>;
  return init<PpcNeuralT<S>>(state, p);
}

template <class S, class CState, class CInput, class COutput>
adcs_status ppc_step(CState* state, const CInput* ci, COutput* co) noexcept {
  PpcNeuralT<S>* c = component<PpcNeuralT<S>>(state);
  if (c == nullptr || ci == nullptr || co == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  EulerTrackingInputT<S> in;
  in.t_s = ci->t_s;
  in.state.theta_BN_rad = from_array(ci->theta_BN_rad);
  in.state.omega_BN_B = from_array(ci->omega_BN_B);
  in.reference.angles = from_array(ci->theta_d_rad);
  in.reference.angles_dot = from_array(ci->theta_dot_d_rad_s);
  in.reference.angles_ddot = from_array(ci->theta_ddot_d_rad_s2);
  BodyTorqueT<S> out;
  const Status s = c->step(in, out);
  to_array(out.torque_B_Nm, co->torque_B_Nm);
  return static_cast<adcs_status>(s);
}

}  // namespace adcs::c_api
