// The C interface (include/adcs/c/adcs.h), seed 004's family in float: adcs_drag_free_adrcf,
// DragFreeAdrcT<float> (the arithmetic: c_api_drag_free.hpp). Its init and step reach no double
// routine on a single-precision FPU (ctest target_m4f_c_api_no_double).
#include "c_api_drag_free.hpp"

static_assert(adcs::c_api::holds<adcs_drag_free_adrcf_state, adcs::DragFreeAdrcT<float>>(),
              "ADCS_DRAG_FREE_ADRCF_STATE_SIZE/_ALIGN");

extern "C" {

adcs_status adcs_drag_free_adrcf_init(const adcs_drag_free_adrcf_params* p, adcs_drag_free_adrcf_state* s) {
  return adcs::c_api::drag_free_adrc_init<float>(p, s);
}
adcs_status adcs_drag_free_adrcf_step(adcs_drag_free_adrcf_state* s, const adcs_drag_free_adrcf_input* in,
                                      adcs_drag_free_adrcf_output* out) {
  return adcs::c_api::drag_free_adrc_step<float>(s, in, out);
}

}  // extern "C"
