// Step benchmarks of the rigid-body + wheel fixtures and seed 001, and the math kernels,
// compiled once for adcs-bench (the benchmarks) and adcs-stepcount (the counted runs).
#include <cmath>

#include "adcs/math/lyapunov.hpp"
#include "adcs/math/pinv.hpp"
#include "adcs/math/place.hpp"
#include "step_fixtures_attitude.hpp"
#include "step_benchmark.hpp"

namespace adcs::bench {
ADCS_STEP_BENCHMARK(MrpPd);
ADCS_STEP_BENCHMARK(RwAllocation);
ADCS_STEP_BENCHMARK(HybridAdaptive);  // seed 001, the paper's estimate update
ADCS_STEP_BENCHMARK(HybridAdaptiveNormalized);  // seed 001, ours for 5-20 Hz
}  // namespace adcs::bench

namespace ADCS_UNITY_ID {
namespace fx = adcs::bench;

// Right pseudo-inverse solve of a 3x4 matrix via LDLT of X X^T, with conditioning report.
void BM_Pinv3x4(benchmark::State& state) {
  adcs::Mat<3, 4> X = fx::four_wheel_axes();
  const adcs::Vec3 v(0.1, 0.2, 0.3);
  adcs::Vec<4> u;
  adcs::PinvInfo info;
  for (auto _ : state) {
    X(0, 3) += 1e-12;
    benchmark::DoNotOptimize(adcs::right_pinv_solve<3, 4>(X, v, u, &info));
    benchmark::DoNotOptimize(u.data());
  }
}
BENCHMARK(BM_Pinv3x4);

// Continuous Lyapunov solve for seed 001's 6x6 A_1 (done once at construction in flight code).
void BM_Lyapunov6(benchmark::State& state) {
  adcs::Mat<3, 6> K;
  const double r2 = std::sqrt(2.0);
  const adcs::AxisPoles<3> poles{{{{{-0.2, 0.2}, {-0.2, -0.2}}},
                                  {{{-0.3, 0.3}, {-0.3, -0.3}}},
                                  {{{-0.2 * r2, 0}, {-0.3 * r2, 0}}}}};
  if (adcs::place_double_integrator<3>(poles, K) != adcs::Status::ok) state.SkipWithError("place");
  adcs::Mat6 A1 = adcs::double_integrator_closed_loop<3>(K);
  adcs::Mat6 P;
  for (auto _ : state) {
    A1(3, 0) -= 1e-15;
    benchmark::DoNotOptimize(adcs::solve_continuous_lyapunov<6>(A1, adcs::Mat6::Identity(), P));
    benchmark::DoNotOptimize(P.data());
  }
}
BENCHMARK(BM_Lyapunov6);
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

namespace adcs::bench {
namespace ADCS_UNITY_ID {
const StepEntry kAttitudeSteps[] = {
    ADCS_STEP_ENTRY(MrpPd),
    ADCS_STEP_ENTRY(RwAllocation),
    ADCS_STEP_ENTRY(HybridAdaptive),
    ADCS_STEP_ENTRY(HybridAdaptiveNormalized),
};
}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
StepTable attitude_steps() noexcept { return step_table(kAttitudeSteps); }
}  // namespace adcs::bench
