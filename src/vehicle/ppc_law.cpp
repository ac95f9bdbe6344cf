#include "vehicle/ppc_law.hpp"

#include <cmath>

namespace adcs::sim::vehicle {

PpcEulerLaw::PpcEulerLaw(const PpcNeuralParams& p) noexcept : law_(p) {}
Status PpcEulerLaw::status() const noexcept { return law_.status(); }
void PpcEulerLaw::reset() noexcept {
  law_.reset();
  last_ = BodyTorque{};
}
double PpcEulerLaw::period_s() const noexcept { return law_.period_s(); }
long PpcEulerLaw::funnel_recoveries() const noexcept { return law_.funnel_recoveries(); }

Status PpcEulerLaw::step(double t_s, const AttitudeState& state, const AttitudeReference& reference, BodyTorque& out,
                         bool& reopened) noexcept {
  reopened = false;
  EulerTrackingInput e;
  e.t_s = t_s;
  e.state = to_euler123(state);
  EulerReferenceSample r;
  const Status rs = to_euler_reference(reference, r);
  if (rs != Status::ok) {  // the target at an Euler gimbal lock: no reference for this law
    out = failure_command(law_.params().gains.on_failure, last_, BodyTorque{});
    return rs;
  }
  constexpr double kTwoPi = 2.0 * kPiRad;
  for (int i = 0; i < 3; ++i) r.angles(i) += kTwoPi * std::round((e.state.theta_BN_rad(i) - r.angles(i)) / kTwoPi);
  e.reference = r;
  PpcNeuralDiagnostics d;
  const Status s = law_.step(e, out, &d);
  reopened = d.funnel_reopened;
  if (usable(s)) last_ = out;
  return s;
}

}  // namespace adcs::sim::vehicle
