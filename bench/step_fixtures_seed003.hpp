#pragma once
// Step fixtures (bench/step_fixtures.hpp): seed 003's SE(3) laws and the composite quantizer.
#include <cmath>
#include <cstdlib>

#include "adcs/actuator/quantizer.hpp"
#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "step_fixtures_common.hpp"

namespace adcs::bench {

// ------------------------------------------------------------------ seed 003 (one 8 Hz command)
//! Chaser and target of the paper's state 1; each step computes the desired state from the target
//! model, then the law (tracking error, G, G⁻¹, Ġξ_e, F0, the target's ξ̇_o feed-forward).
template <class Law>
struct Se3Step {
  Se3ScenarioParams sp;
  Se3Spacecraft target_model{se3_target_params(sp)};
  Se3SpacecraftState target, chaser;
  Law law;
  Vec6 u;
  explicit Se3Step(const typename Law::Params& p) : law(p, se3_chaser_nominal_params(sp)) {
    if (se3_target_initial_state(sp, target) != Status::ok) std::abort();
    chaser = se3_chaser_initial_state(target, kSe3InitialPoses[0]);
  }
  void operator()() noexcept {
    chaser.R_N(0) += 1e-9;
    Se3DesiredState d;
    escape(se3_desired_state(target_model, target, sp, d));
    escape(law.step(chaser, d, u));
    escape(u);
  }
};
struct SE3PrescribedTimeStep : Se3Step<PrescribedTimeSe3> {
  SE3PrescribedTimeStep() : Se3Step(PrescribedTimeSe3Params{}) {}
};
struct SE3FtsmcStep : Se3Step<FtsmcSe3> {
  SE3FtsmcStep() : Se3Step(FtsmcSe3Params{}) {}
};

//! sat → composite quantizer on the six SE(3) channels (seed 003 Table 1 parameters).
struct CompositeQuantizerStep {
  CompositeQuantizer<6> q{seed003_quantizer_params()};
  Vec6 u = (Vec6() << 0.3, -0.01, 0.002, 4.0, -0.5, 0.03).finished(), u_c;
  Vec6 limit = (Vec6() << 0.5, 0.5, 0.5, 5.0, 5.0, 5.0).finished();
  double k = 0.0;
  void operator()() noexcept {
    u(0) = 0.3 * std::sin(1e-3 * k);
    k += 1.0;
    escape(saturate_then_quantize<6>(u, limit, q, u_c));
    escape(u_c);
  }
};

}  // namespace adcs::bench
