// libFuzzer harness, seed 002: PpcNeural (PPATC: funnel transform + RBF + adaptive bound) and
// AdaptiveTracking (ATC), in both angle-unit conventions, PPATC with and without the robust clamp
// and with and without the funnel recovery (issue 15).
// Input format: fuzz_common.hpp; first byte = law, second = configuration.
//
// Asserted on every step (besides "no crash, no sanitizer report"):
//  - the torque command is finite, whatever the status;
//  - a non-finite input gives exactly non_finite_input;
//  - a status that is not usable() leaves the command at the last applied one and the RBF
//    weights Ŵ, the bound estimate μ̂ and (PPATC) the funnel branches bitwise unchanged;
//  - an applied step keeps Ŵ finite and μ̂ finite and >= 0 (spec B-S12), and reports
//    constraint_violated only in robust-clamp mode or when it re-opened the funnel;
//  - a re-opening (PPATC, recovery = reopen) is counted exactly once, only on an applied step,
//    starts the re-opened channels at in.t_s with a valid performance function (ρ0' > ρ∞), and is
//    flagged in the diagnostics; without the recovery the count stays 0.
//  - RbfCompensator::set_state (warm start) refuses non-finite values and μ̂ < 0 untouched.
#include <array>
#include <cstdint>

#include "adcs/control/adaptive_tracking.hpp"
#include "adcs/control/ppc_neural.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/plant/flexible_configurations.hpp"  // seed002_tracking_gains()
#include "adcs/reference/sinusoidal_euler.hpp"
#include "fuzz_common.hpp"

// File-local, and named: the five harnesses are compiled in one unit (tests/fuzz/CMakeLists.txt).
namespace ADCS_UNITY_ID {
using adcs::Status;
using adcs::Vec3;
constexpr int kMaxSteps = 12;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

adcs::PpcNeuralParams ppc_params(int config) {
  adcs::PpcNeuralParams p{adcs::seed002_tracking_gains(), adcs::seed002_performance()};
  p.gains.units = (config & 1) ? adcs::AngleUnits::degrees : adcs::AngleUnits::radians;
  p.ppc.robust_clamp = (config & 2) != 0;
  p.ppc.recovery = (config & 16) ? adcs::FunnelRecovery::reopen : adcs::FunnelRecovery::none;
  return p;
}

const adcs::PpcNeural& ppc_proto(int config) {
  static const adcs::PpcNeural protos[8] = {
      adcs::PpcNeural(ppc_params(0)),  adcs::PpcNeural(ppc_params(1)),  adcs::PpcNeural(ppc_params(2)),
      adcs::PpcNeural(ppc_params(3)),  adcs::PpcNeural(ppc_params(16)), adcs::PpcNeural(ppc_params(17)),
      adcs::PpcNeural(ppc_params(18)), adcs::PpcNeural(ppc_params(19))};
  return protos[(config & 3) | ((config & 16) >> 2)];
}

const adcs::AdaptiveTracking& atc_proto(int config) {
  static const adcs::AdaptiveTracking protos[2] = {
      adcs::AdaptiveTracking(adcs::AdaptiveTrackingParams{ppc_params(0).gains}),
      adcs::AdaptiveTracking(adcs::AdaptiveTrackingParams{ppc_params(1).gains})};
  return protos[config & 1];
}

template <class Law>
struct Snapshot {
  adcs::Mat<7, 3> W;
  double mu;
  std::array<adcs::PpcBranch, 3> branch{};
  std::array<double, 3> t0{}, rho0{};  // the funnel in force (PPATC)
  long recoveries = 0;
  explicit Snapshot(Law& law) : W(law.weights()), mu(law.mu()) {
    if constexpr (std::is_same_v<Law, adcs::PpcNeural>) {
      for (int i = 0; i < 3; ++i) {
        const auto u = static_cast<std::size_t>(i);
        branch[u] = law.branch(i);
        t0[u] = law.funnel().start_time(i);
        rho0[u] = law.funnel().active(i).rho0;
      }
      recoveries = law.funnel_recoveries();
    }
  }
  bool operator==(const Snapshot& o) const {
    bool funnel = branch == o.branch && recoveries == o.recoveries;
    for (std::size_t i = 0; i < 3; ++i) funnel = funnel && fuzz::same_bits(t0[i], o.t0[i]) && fuzz::same_bits(rho0[i], o.rho0[i]);
    return fuzz::same_bits_mat(W, o.W) && fuzz::same_bits(mu, o.mu) && funnel;
  }
};

template <class Law>
void run(Law& law, int config, fuzz::Reader& r) {
  if (config & 4) {  // warm start: fuzzed Ŵ, μ̂ (reaches large robust terms and overflow paths)
    adcs::Mat<7, 3> W;
    for (int j = 0; j < 3; ++j) W.col(j) = r.vec<7>();
    const double mu = r.value();
    const Snapshot<Law> before(law);
    const Status s = law.compensator().set_state(W, mu);
    if (!fuzz::finite(W) || !fuzz::finite(mu))
      FUZZ_CHECK(s == Status::non_finite_input, "RbfCompensator::set_state: non-finite accepted");
    else if (mu < 0.0)
      FUZZ_CHECK(s == Status::out_of_range, "RbfCompensator::set_state: mu < 0 accepted");
    if (s != Status::ok) FUZZ_CHECK(Snapshot<Law>(law) == before, "set_state: rejected but changed");
  }
  const adcs::SinusoidalEulerReference ref;
  const bool robust = std::is_same_v<Law, adcs::PpcNeural> && (config & 2);
  const bool reopen = std::is_same_v<Law, adcs::PpcNeural> && (config & 16);
  adcs::BodyTorque last;  // the last applied command (zero after construction)
  typename Law::Diagnostics diag;
  for (int k = 0; k < kMaxSteps && !r.empty(); ++k) {
    adcs::EulerTrackingInput in;
    in.t_s = 1e-4 * k + r.value();
    const adcs::EulerReferenceSample nominal = ref.sample(std::isfinite(in.t_s) ? in.t_s : 0.0);
    in.state.theta_BN_rad = nominal.angles + Vec3(0.25, 0.15, -0.2) * kDeg + r.vec<3>();  // inside ρ0 = 0.3°
    in.state.omega_BN_B = r.vec<3>();
    adcs::EulerReferenceSample& rs = in.reference;
    rs = nominal;
    rs.angles += r.vec<3>();
    rs.angles_dot += r.vec<3>();
    rs.angles_ddot += r.vec<3>();
    const bool finite_in = fuzz::finite(in.t_s) && fuzz::finite(in.state.theta_BN_rad) &&
                           fuzz::finite(in.state.omega_BN_B) && fuzz::finite(rs.angles) &&
                           fuzz::finite(rs.angles_dot) && fuzz::finite(rs.angles_ddot);
    const Snapshot<Law> before(law);
    adcs::BodyTorque out;
    out.torque_B_Nm.setConstant(fuzz::kNaN);  // must be overwritten
    const Status s = law.step(in, out, (config & 8) ? &diag : nullptr);
    if constexpr (std::is_same_v<Law, adcs::PpcNeural>)
      fuzz::stat(0, "PpcNeural", s);
    else
      fuzz::stat(1, "AdaptiveTracking", s);
    FUZZ_CHECK(fuzz::finite(out.torque_B_Nm), "Euler tracking law: non-finite command");
    fuzz::check_status_vs_input(s, finite_in, "Euler tracking law: non-finite input not rejected");
    const Snapshot<Law> after(law);
    if (!fuzz::applied(s)) {
      FUZZ_CHECK(after == before, "Euler tracking law: rejected step changed Ŵ, μ̂, the funnel or its count");
      FUZZ_CHECK(fuzz::is_failure_command(adcs::FailurePolicy::safe_command, out.torque_B_Nm, last.torque_B_Nm),
                 "Euler tracking law: rejected step did not output the failure command (zero torque)");
      continue;
    }
    const bool reopened = after.recoveries != before.recoveries;
    if (reopened) fuzz::stat(2, "PpcNeural reopened", s);
    FUZZ_CHECK(!reopened || (reopen && after.recoveries == before.recoveries + 1 && s == Status::constraint_violated),
               "PpcNeural: funnel re-opened without the recovery, more than once, or not flagged");
    FUZZ_CHECK(s == Status::ok || (s == Status::constraint_violated && (robust || reopened)),
               "Euler tracking law: undocumented usable status");
    if constexpr (std::is_same_v<Law, adcs::PpcNeural>) {
      if ((config & 8) && reopened) FUZZ_CHECK(diag.funnel_reopened, "PpcNeural: re-opening not in the diagnostics");
      for (int i = 0; i < 3 && reopened; ++i) {
        const auto u = static_cast<std::size_t>(i);
        if (fuzz::same_bits(after.t0[u], before.t0[u]) && fuzz::same_bits(after.rho0[u], before.rho0[u])) continue;
        FUZZ_CHECK(fuzz::same_bits(after.t0[u], in.t_s) && adcs::valid(law.funnel().active(i)),
                   "PpcNeural: re-opened channel not started at in.t_s with a valid performance function");
      }
    }
    FUZZ_CHECK(fuzz::finite(after.W) && fuzz::finite(after.mu) && after.mu >= 0.0,
               "Euler tracking law: committed a non-finite or negative estimate");
    last = out;
  }
}
}  // namespace ADCS_UNITY_ID

ADCS_FUZZ_ENTRY(fuzz_seed002) {
  using namespace ADCS_UNITY_ID;
  fuzz::Reader r(data, size);
  const int law = r.u8() & 1;
  const int config = r.u8();
  if (law == 0) {
    adcs::PpcNeural ctrl = ppc_proto(config);
    run(ctrl, config, r);
  } else {
    adcs::AdaptiveTracking ctrl = atc_proto(config);
    run(ctrl, config, r);
  }
  return 0;
}
