// The C interface (include/adcs/c/adcs.h), seed 003's family in float: adcs_se3_ptcf,
// PrescribedTimeSe3T<float> (the arithmetic: c_api_se3.hpp). Its init and step reach no double
// routine on a single-precision FPU (ctest target_m4f_c_api_no_double).
#include "c_api_se3.hpp"

static_assert(adcs::c_api::holds<adcs_se3_ptcf_state, adcs::PrescribedTimeSe3T<float>>(),
              "ADCS_SE3_PTCF_STATE_SIZE/_ALIGN");

extern "C" {

adcs_status adcs_se3_ptcf_init(const adcs_se3_ptcf_params* p, adcs_se3_ptcf_state* s) {
  return adcs::c_api::se3_ptc_init<float>(p, s);
}
adcs_status adcs_se3_ptcf_step(adcs_se3_ptcf_state* s, const adcs_se3_ptcf_input* in, adcs_se3_ptcf_output* out) {
  return adcs::c_api::se3_ptc_step<float>(s, in, out);
}

}  // extern "C"
