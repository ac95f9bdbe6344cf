// The C interface (include/adcs/c/adcs.h), seed 002's family in float: adcs_ppcf,
// PpcNeuralT<float> (the arithmetic: c_api_ppc.hpp). Its init and step reach no double routine on
// a single-precision FPU (ctest target_m4f_c_api_no_double).
#include "c_api_ppc.hpp"

static_assert(adcs::c_api::holds<adcs_ppcf_state, adcs::PpcNeuralT<float>>(), "ADCS_PPCF_STATE_SIZE/_ALIGN");

extern "C" {

adcs_status adcs_ppcf_init(const adcs_ppcf_params* p, adcs_ppcf_state* s) { return adcs::c_api::ppc_init<float>(p, s); }
adcs_status adcs_ppcf_step(adcs_ppcf_state* s, const adcs_ppcf_input* in, adcs_ppcf_output* out) {
  return adcs::c_api::ppc_step<float>(s, in, out);
}

}  // extern "C"
