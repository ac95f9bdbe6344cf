// The C interface (include/adcs/c/adcs.h), seed 002's family in double: adcs_ppc,
// PpcNeuralT<double> (the arithmetic: c_api_ppc.hpp).
#include "c_api_ppc.hpp"

static_assert(adcs::c_api::holds<adcs_ppc_state, adcs::PpcNeuralT<double>>(), "ADCS_PPC_STATE_SIZE/_ALIGN");

extern "C" {

adcs_status adcs_ppc_init(const adcs_ppc_params* p, adcs_ppc_state* s) { return adcs::c_api::ppc_init<double>(p, s); }
adcs_status adcs_ppc_step(adcs_ppc_state* s, const adcs_ppc_input* in, adcs_ppc_output* out) {
  return adcs::c_api::ppc_step<double>(s, in, out);
}

}  // extern "C"
