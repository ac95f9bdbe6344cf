// Seed 003's C family (include/adcs/c/adcs.h: adcs_se3_ptc, adcs_se3_ptcf), shared by its two
// units: adcs_c_se3.cpp (double) and adcs_c_se3_f.cpp (float), PrescribedTimeSe3T<S>, the
// prescribed-time backstepping law on SE(3). One unit per scalar, as seed 002's (c_api_ppc.hpp).
// Private to src/c.
#pragma once

#include "adcs/c/adcs.h"
#include "adcs/control/prescribed_time_se3.hpp"
#include "c_api_common.hpp"

namespace adcs::c_api {

template <class S, class CParams, class CState>
adcs_status se3_ptc_init(const CParams* cp, CState* state) noexcept {
  if (cp == nullptr || state == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  PrescribedTimeSe3ParamsT<S> p;
  p.p = cp->p;
  p.T = cp->T_s;
  p.K2 = from_array(cp->K2);
  p.Lambda = from_array(cp->Lambda);
  p.Upsilon = from_array(cp->Upsilon);
  p.eps1 = cp->eps1;
  p.K3 = from_array(cp->K3);
  p.Lambda2 = from_array(cp->Lambda2);
  p.Upsilon2 = from_array(cp->Upsilon2);
  p.eps2 = cp->eps2;
  p.zeta = from_array(cp->zeta);
  p.eps_q = cp->eps_q;
  p.a = cp->a;
  p.gamma = cp->gamma;
  p.sigma1 = cp->sigma1;
  p.sigma2 = cp->sigma2;
  p.psi_hat0 = cp->psi_hat0;
  p.period_s = cp->period_s;
  p.nominal.J_B = from_rows(cp->J0_kgm2);
  p.nominal.m = cp->m0_kg;
  p.nominal.env.mu = cp->mu_m3_s2;
  p.nominal.env.J2 = cp->J2;
  p.nominal.env.R_E = cp->R_E_m;
  // An out-of-range policy refuses the set (as a NaN gain does), never an invalid enum.
  if (!policy(cp->on_failure, p.on_failure)) p.period_s = unset_v<S>;
  return init<PrescribedTimeSe3T<S>>(state, p);
}

template <class S, class CState, class CInput, class COutput>
adcs_status se3_ptc_step(CState* state, const CInput* ci, COutput* co) noexcept {
  PrescribedTimeSe3T<S>* c = component<PrescribedTimeSe3T<S>>(state);
  if (c == nullptr || ci == nullptr || co == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  Se3TrackingInputT<S> in;
  in.state.C_NB = from_rows(ci->C_NB);
  in.state.R_N = from_array(ci->R_N_m);
  in.state.omega_BN_B = from_array(ci->omega_BN_B);
  in.state.v_B = from_array(ci->v_B_m_s);
  in.desired.C_ND = from_rows(ci->C_ND);
  in.desired.R_N = from_array(ci->R_d_N_m);
  in.desired.omega_DN_D = from_array(ci->omega_DN_D);
  in.desired.v_D = from_array(ci->v_D_m_s);
  in.desired.omega_dot_D = from_array(ci->omega_dot_D);
  in.desired.v_dot_D = from_array(ci->v_dot_D_m_s2);
  WrenchT<S> out;
  const Status s = c->step(in, out);
  to_array(out.torque_B_Nm, co->torque_B_Nm);
  to_array(out.force_B_N, co->force_B_N);
  return static_cast<adcs_status>(s);
}

}  // namespace adcs::c_api
