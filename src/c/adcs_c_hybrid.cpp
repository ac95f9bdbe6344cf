// The C interface (include/adcs/c/adcs.h), seed 001's family: HybridAdaptive<4, 3, S>, the
// adaptive MIMO law for 4 CMGs + 3 reaction wheels, in double (adcs_hybrid43) and float
// (adcs_hybrid43f), built from ground-designed gains (the two-argument constructor: no pole
// placement or Lyapunov solve on board), and that ground design in double
// (adcs_hybrid_design_gains). A unit of its own so that a flight build compiles it only if it
// links it. Layout and checks: c_api_common.hpp.
#include "adcs/c/adcs.h"

#include "adcs/control/hybrid_adaptive.hpp"
#include "c_api_common.hpp"

namespace adcs::c_api {
namespace {

using Hybrid43 = HybridAdaptive<4, 3, double>;
using Hybrid43f = HybridAdaptive<4, 3, float>;
static_assert(holds<adcs_hybrid43_state, Hybrid43>(), "ADCS_HYBRID43_STATE_SIZE/_ALIGN");
static_assert(holds<adcs_hybrid43f_state, Hybrid43f>(), "ADCS_HYBRID43F_STATE_SIZE/_ALIGN");
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
  HybridAdaptive<4, 3, S>* c = ::new (static_cast<void*>(state->opaque)) HybridAdaptive<4, 3, S>(p, gains);
  write_tag(*state, kInitialised);
  return static_cast<adcs_status>(c->status());
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

adcs_status design_gains(const double (*re)[2], const double (*im)[2], const double (*Q_L)[6], double (*K)[6],
                         double (*P)[6]) noexcept {
  if (re == nullptr || im == nullptr || Q_L == nullptr || K == nullptr || P == nullptr)
    return ADCS_STATUS_INVALID_PARAMETER;
  AxisPoles<3> poles;
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < 2; ++k) poles[a][k] = {re[a][k], im[a][k]};
  HybridAdaptiveGains<double> g;
  const Mat6 Q = Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(&Q_L[0][0]);
  const Status s = design_hybrid_adaptive_gains(poles, Q, g);
  if (s != Status::ok) return static_cast<adcs_status>(s);
  Eigen::Map<Eigen::Matrix<double, 3, 6, Eigen::RowMajor>> K_out(&K[0][0]);
  Eigen::Map<Eigen::Matrix<double, 6, 6, Eigen::RowMajor>> P_out(&P[0][0]);
  K_out = g.K;
  P_out = g.P;
  return ADCS_STATUS_OK;
}

}  // namespace
}  // namespace adcs::c_api

extern "C" {

adcs_status adcs_hybrid43_init(const adcs_hybrid43_params* p, adcs_hybrid43_state* s) {
  return adcs::c_api::hybrid_init<double>(p, s);
}
adcs_status adcs_hybrid43_step(adcs_hybrid43_state* s, const adcs_hybrid43_input* in, adcs_hybrid43_output* out) {
  return adcs::c_api::hybrid_step<double>(s, in, out);
}
adcs_status adcs_hybrid43f_init(const adcs_hybrid43f_params* p, adcs_hybrid43f_state* s) {
  return adcs::c_api::hybrid_init<float>(p, s);
}
adcs_status adcs_hybrid43f_step(adcs_hybrid43f_state* s, const adcs_hybrid43f_input* in, adcs_hybrid43f_output* out) {
  return adcs::c_api::hybrid_step<float>(s, in, out);
}
adcs_status adcs_hybrid_design_gains(const double poles_re[3][2], const double poles_im[3][2], const double Q_L[6][6],
                                     double K[3][6], double P[6][6]) {
  return adcs::c_api::design_gains(poles_re, poles_im, Q_L, K, P);
}

}  // extern "C"
