// Seed 001's C family (include/adcs/c/adcs.h: adcs_hybrid43, adcs_hybrid43f), shared by its two
// units: adcs_c_hybrid.cpp (double) and adcs_c_hybrid_f.cpp (float). HybridAdaptive<4, 3, S> is
// built from ground-designed gains (the two-argument constructor: no pole placement or Lyapunov
// solve on board); the design itself is adcs_c_hybrid_design.cpp. One unit per scalar so that a
// flight build compiles only the precision it links: a Cortex-M4F build the float family, whose
// double twin would be software double there. Private to src/c.
#pragma once

#include "adcs/c/adcs.h"
#include "adcs/control/hybrid_adaptive.hpp"
#include "c_api_common.hpp"

namespace adcs::c_api {

static_assert(ADCS_ADAPTATION_EXPLICIT_EULER == static_cast<int>(AdaptationStep::explicit_euler), "step ABI");
static_assert(ADCS_ADAPTATION_NORMALIZED == static_cast<int>(AdaptationStep::normalized), "step ABI");

template <class S, class CParams, class CState>
adcs_status hybrid_init(const CParams* cp, CState* state) noexcept {
  if (cp == nullptr || state == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  HybridAdaptiveParams<4, 3, S> p;
  VscmgGeometry<4, 3, S>& g = p.nominal;
  g.A_cg = from_rows(cp->A_cg);
  g.A_cs0 = from_rows(cp->A_cs0);
  g.A_ct0 = from_rows(cp->A_ct0);
  g.A_ws = from_rows(cp->A_ws);
  g.I_cs = from_array(cp->I_cs);
  g.I_ct = from_array(cp->I_ct);
  g.I_cg = from_array(cp->I_cg);
  g.h_cw = from_array(cp->h_cw);
  g.I_wws = from_array(cp->I_wws);
  g.J_s = from_rows(cp->J_s);
  p.Q_L = from_rows(cp->Q_L);
  p.alpha_F = cp->alpha_F;
  p.alpha_G = cp->alpha_G;
  p.beta_G = cp->beta_G;
  p.delta_G = cp->delta_G;
  p.H_I_n = from_array(cp->H_I_n);
  p.period_s = cp->period_s;
  p.steering = SteeringParamsT<S>{cp->steering_sigma_threshold, cp->steering_lambda_max,
                                  cp->steering_max_torque_error};
  p.max_step_gain = cp->max_step_gain;
  // Out-of-range enumerations refuse the set (as a NaN gain does), never an invalid enum.
  if (cp->adaptation_step == ADCS_ADAPTATION_EXPLICIT_EULER || cp->adaptation_step == ADCS_ADAPTATION_NORMALIZED)
    p.adaptation_step = static_cast<AdaptationStep>(cp->adaptation_step);
  else
    p.period_s = unset_v<S>;
  if (!policy(cp->on_failure, p.on_failure)) p.period_s = unset_v<S>;
  HybridAdaptiveGains<S> gains;
  gains.K = from_rows(cp->K);
  gains.P = from_rows(cp->P);
  return init<HybridAdaptive<4, 3, S>>(state, p, gains);
}

template <class S, class CState, class CInput, class COutput>
adcs_status hybrid_step(CState* state, const CInput* ci, COutput* co) noexcept {
  HybridAdaptive<4, 3, S>* c = component<HybridAdaptive<4, 3, S>>(state);
  if (c == nullptr || ci == nullptr || co == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  HybridAdaptiveInput<4, 3, S> in;  // reference ω_f, ω̇_f: not read by the law
  in.state.sigma_BN = from_array(ci->sigma_BN);
  in.state.omega_BN_B = from_array(ci->omega_BN_B);
  in.actuators.gamma_rad = from_array(ci->gamma_rad);
  in.actuators.Omega_rad_s = from_array(ci->Omega_rad_s);
  in.reference.sigma = from_array(ci->sigma_d);
  in.reference.sigma_dot = from_array(ci->sigma_dot_d);
  in.reference.sigma_ddot = from_array(ci->sigma_ddot_d);
  VscmgRates<4, 3, S> out;
  const Status s = c->step(in, out);
  to_array(out.gamma_dot_rad_s, co->gamma_dot_rad_s);
  to_array(out.Omega_dot_rad_s2, co->Omega_dot_rad_s2);
  return static_cast<adcs_status>(s);
}

}  // namespace adcs::c_api
