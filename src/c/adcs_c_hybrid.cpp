// The C interface (include/adcs/c/adcs.h), seed 001's family in double: adcs_hybrid43,
// HybridAdaptive<4, 3, double> (the arithmetic: c_api_hybrid.hpp).
#include "c_api_hybrid.hpp"

static_assert(adcs::c_api::holds<adcs_hybrid43_state, adcs::HybridAdaptive<4, 3, double>>(),
              "ADCS_HYBRID43_STATE_SIZE/_ALIGN");

extern "C" {

adcs_status adcs_hybrid43_init(const adcs_hybrid43_params* p, adcs_hybrid43_state* s) {
  return adcs::c_api::hybrid_init<double>(p, s);
}
adcs_status adcs_hybrid43_step(adcs_hybrid43_state* s, const adcs_hybrid43_input* in, adcs_hybrid43_output* out) {
  return adcs::c_api::hybrid_step<double>(s, in, out);
}

}  // extern "C"
