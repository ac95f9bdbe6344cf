// The C interface (include/adcs/c/adcs.h), seed 001's family in float: adcs_hybrid43f,
// HybridAdaptive<4, 3, float> (the arithmetic: c_api_hybrid.hpp). Its init and step reach no double
// routine on a single-precision FPU (ctest target_m4f_c_api_no_double).
#include "c_api_hybrid.hpp"

static_assert(adcs::c_api::holds<adcs_hybrid43f_state, adcs::HybridAdaptive<4, 3, float>>(),
              "ADCS_HYBRID43F_STATE_SIZE/_ALIGN");

extern "C" {

adcs_status adcs_hybrid43f_init(const adcs_hybrid43f_params* p, adcs_hybrid43f_state* s) {
  return adcs::c_api::hybrid_init<float>(p, s);
}
adcs_status adcs_hybrid43f_step(adcs_hybrid43f_state* s, const adcs_hybrid43f_input* in, adcs_hybrid43f_output* out) {
  return adcs::c_api::hybrid_step<float>(s, in, out);
}

}  // extern "C"
