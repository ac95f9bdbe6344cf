// The C interface (include/adcs/c/adcs.h), seed 003's family in double: adcs_se3_ptc,
// PrescribedTimeSe3T<double> (the arithmetic: c_api_se3.hpp).
#include "c_api_se3.hpp"

static_assert(adcs::c_api::holds<adcs_se3_ptc_state, adcs::PrescribedTimeSe3T<double>>(),
              "ADCS_SE3_PTC_STATE_SIZE/_ALIGN");

extern "C" {

adcs_status adcs_se3_ptc_init(const adcs_se3_ptc_params* p, adcs_se3_ptc_state* s) {
  return adcs::c_api::se3_ptc_init<double>(p, s);
}
adcs_status adcs_se3_ptc_step(adcs_se3_ptc_state* s, const adcs_se3_ptc_input* in, adcs_se3_ptc_output* out) {
  return adcs::c_api::se3_ptc_step<double>(s, in, out);
}

}  // extern "C"
