// The C interface (include/adcs/c/adcs.h), seed 004's family in double: adcs_drag_free_adrc,
// DragFreeAdrcT<double> (the arithmetic: c_api_drag_free.hpp).
#include "c_api_drag_free.hpp"

static_assert(adcs::c_api::holds<adcs_drag_free_adrc_state, adcs::DragFreeAdrcT<double>>(),
              "ADCS_DRAG_FREE_ADRC_STATE_SIZE/_ALIGN");

extern "C" {

adcs_status adcs_drag_free_adrc_init(const adcs_drag_free_adrc_params* p, adcs_drag_free_adrc_state* s) {
  return adcs::c_api::drag_free_adrc_init<double>(p, s);
}
adcs_status adcs_drag_free_adrc_step(adcs_drag_free_adrc_state* s, const adcs_drag_free_adrc_input* in,
                                     adcs_drag_free_adrc_output* out) {
  return adcs::c_api::drag_free_adrc_step<double>(s, in, out);
}

}  // extern "C"
