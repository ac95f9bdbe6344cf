// Cortex-M7 instantiation unit 3 of 5 (see instantiate_attitude.cpp): seed 003, SE(3) tracking
// with both laws, then saturation and the composite quantizer (functions and components).
#include "adcs/actuator/quantizer.hpp"
#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/math/se3.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace adcs {
template class CompositeQuantizer<6>;
template class SaturatedQuantizer<6>;
template class Saturation<6>;
template Status saturate_then_quantize<6>(const Vec<6>&, const Vec<6>&, CompositeQuantizer<6>&, Vec<6>&,
                                          std::uint32_t*) noexcept;
}  // namespace adcs

extern "C" int adcs_target_smoke_seed003(const double* /*in*/, double* out) {
  adcs::Se3ScenarioParams sp;
  adcs::Se3SpacecraftState target;
  const adcs::Status s9 = adcs::se3_target_initial_state(sp, target);
  const adcs::Se3SpacecraftState chaser = adcs::se3_chaser_initial_state(target, adcs::kSe3InitialPoses[0]);
  adcs::Se3DesiredState desired;
  const adcs::Status s10 = adcs::se3_desired_state(adcs::Se3Spacecraft(adcs::se3_target_params(sp)), target, sp, desired);
  adcs::PrescribedTimeSe3Params pp;
  pp.zeta = adcs::quantization_compensation_gain(adcs::seed003_quantizer_params());
  pp.nominal = adcs::se3_chaser_nominal_params(sp);
  adcs::PrescribedTimeSe3 ptc(pp);
  adcs::FtsmcSe3Params fp;
  fp.nominal = pp.nominal;
  adcs::FtsmcSe3 ftsmc(fp);
  adcs::CompositeQuantizer<6> quantizer(adcs::seed003_quantizer_params());
  const adcs::Se3TrackingInput law_in{chaser, desired};
  adcs::Wrench w;
  const adcs::Status s11 = adcs::worst(ptc.step(law_in, w), ftsmc.step(law_in, w));
  const adcs::Vec6 u6 = w.stacked();
  adcs::Vec6 u6c;
  const adcs::Status s12 = adcs::saturate_then_quantize<6>(u6, adcs::se3_actuator_limits(sp), quantizer, u6c);
  out[3] = u6c.sum() + adcs::se3_log(adcs::se3_exp(u6)).sum();
  return static_cast<int>(s9) + static_cast<int>(s10) + static_cast<int>(s11) + static_cast<int>(s12);
}
