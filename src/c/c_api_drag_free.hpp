// Seed 004's C family (include/adcs/c/adcs.h: adcs_drag_free_adrc, adcs_drag_free_adrcf), shared
// by its two units: adcs_c_drag_free.cpp (double) and adcs_c_drag_free_f.cpp (float),
// DragFreeAdrcT<S>, the drag-free satellite's ADRC. One unit per scalar, as seed 002's
// (c_api_ppc.hpp). Private to src/c.
#pragma once

#include "adcs/c/adcs.h"
#include "adcs/control/adrc.hpp"
#include "c_api_common.hpp"

namespace adcs::c_api {

static_assert(ADCS_ADRC_INTEGRAL_SCALED_SUM == static_cast<int>(IntegralForm::scaled_sum), "ADRC ABI");
static_assert(ADCS_ADRC_INTEGRAL_RAW_SUM == static_cast<int>(IntegralForm::raw_sum), "ADRC ABI");
static_assert(ADCS_ADRC_X_NLPID == static_cast<int>(DragFreeXLaw::nlpid), "ADRC ABI");
static_assert(ADCS_ADRC_X_PID == static_cast<int>(DragFreeXLaw::pid), "ADRC ABI");
static_assert(ADCS_ADRC_X_PID_COMPENSATED == static_cast<int>(DragFreeXLaw::pid_compensated), "ADRC ABI");

template <class S>
NlpidGainsT<S> nlpid_gains(const S (&k)[3]) noexcept {
  return NlpidGainsT<S>{k[0], k[1], k[2]};
}

template <class S, class CParams, class CState>
adcs_status drag_free_adrc_init(const CParams* cp, CState* state) noexcept {
  if (cp == nullptr || state == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  // The plant's sensor ranges and noise densities keep DragFreeParams' (seed 004 Table 2) values:
  // the law does not read them, and the validation they enter (valid(plant)) accepts them.
  DragFreeAdrcParamsT<S> p;
  p.plant.m_tm = cp->m_tm_kg;
  p.plant.m_sc = cp->m_sc_kg;
  p.plant.I_tm = from_rows(cp->I_tm_kgm2);
  p.plant.I_sc = from_rows(cp->I_sc_kgm2);
  p.plant.K_trans = from_rows(cp->K_trans_N_m);
  p.plant.D_trans = from_rows(cp->D_trans_Ns_m);
  p.plant.K_rot = from_rows(cp->K_rot_Nm_rad);
  p.plant.D_rot = from_rows(cp->D_rot_Nms_rad);
  p.plant.period_s = cp->period_s;
  p.attitude = nlpid_gains(cp->attitude);
  p.drag_free = nlpid_gains(cp->drag_free);
  p.tm_attitude = nlpid_gains(cp->tm_attitude);
  p.alpha = cp->alpha;
  p.delta = cp->delta;
  p.limit = cp->limit;
  p.pid_kp = cp->pid_kp;
  p.pid_ki = cp->pid_ki;
  p.pid_kd = cp->pid_kd;
  // An out-of-range enumerator or policy refuses the set (as a NaN gain does), never an invalid enum.
  const bool enums_ok = (cp->integral == ADCS_ADRC_INTEGRAL_SCALED_SUM || cp->integral == ADCS_ADRC_INTEGRAL_RAW_SUM) &&
                        cp->x_law >= ADCS_ADRC_X_NLPID && cp->x_law <= ADCS_ADRC_X_PID_COMPENSATED &&
                        policy(cp->on_failure, p.on_failure);
  if (enums_ok) {
    p.integral = static_cast<IntegralForm>(cp->integral);
    p.x_law = static_cast<DragFreeXLaw>(cp->x_law);
  } else {
    p.limit = unset_v<S>;
  }
  return init<DragFreeAdrcT<S>>(state, p);
}

template <class S, class CState, class CInput, class COutput>
adcs_status drag_free_adrc_step(CState* state, const CInput* ci, COutput* co) noexcept {
  DragFreeAdrcT<S>* c = component<DragFreeAdrcT<S>>(state);
  if (c == nullptr || ci == nullptr || co == nullptr) return ADCS_STATUS_INVALID_PARAMETER;
  DragFreeAdrcInputT<S> in;
  in.x_hat = from_array(ci->x_hat);
  in.F_D_hat_N = from_array(ci->F_D_hat_N);
  in.phi_sc_cmd_rad = from_array(ci->phi_sc_cmd_rad);
  DragFreeActuationT<S> out;
  const Status s = c->step(in, out);
  to_array(out.T_Csc_Nm, co->T_Csc_Nm);
  to_array(out.F_Csc_N, co->F_Csc_N);
  to_array(out.T_Ctm_Nm, co->T_Ctm_Nm);
  return static_cast<adcs_status>(s);
}

}  // namespace adcs::c_api
