// run_sampled_data: sample times, call counts, the final partial interval, ZOH and normalize().
#include <gtest/gtest.h>

#include <vector>

#include "sim/cvode_integrator.hpp"
#include "sim/rk4_integrator.hpp"
#include "sim/sampled_data.hpp"

namespace ADCS_UNITY_ID {

using adcs::sim::SampledDataOptions;
using adcs::sim::SimError;

// x' = u; normalize() flips the sign when x > 1 (a stand-in for the MRP shadow switch) and
// counts its calls.
struct FlippingIntegrator {
  static constexpr int kStateSize = 1;
  static constexpr int kInputSize = 1;
  using State = adcs::Vec<kStateSize>;
  using Input = adcs::Vec<kInputSize>;
  int* normalize_calls = nullptr;
  void derivative(double /*t*/, const State& /*x*/, const Input& u, State& xdot) const noexcept {
    xdot = u;
  }
  bool normalize(State& x) const noexcept {
    ++*normalize_calls;
    if (x(0) <= 1.0) return false;
    x(0) = -x(0);
    return true;
  }
};
static_assert(adcs::sim::has_normalize_v<FlippingIntegrator>);

struct Trace {
  std::vector<double> controller_t, observer_t, observer_x, observer_u, u_on_entry;
};

template <class Integrator>
Trace run(const FlippingIntegrator& plant, Integrator& integrator, FlippingIntegrator::State& x,
          const SampledDataOptions& options) {
  Trace trace;
  adcs::sim::run_sampled_data(
      plant, integrator, x, options,
      [&](double t, const FlippingIntegrator::State& /*x*/, FlippingIntegrator::Input& u) {
        trace.controller_t.push_back(t);
        trace.u_on_entry.push_back(u(0));
        u(0) = 3.0;  // [1/s]
      },
      [&](double t, const FlippingIntegrator::State& xs, const FlippingIntegrator::Input& u) {
        trace.observer_t.push_back(t);
        trace.observer_x.push_back(xs(0));
        trace.observer_u.push_back(u(0));
      });
  return trace;
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

TEST(SampledData, SampleTimesCountsPartialIntervalAndNormalize) {
  int normalize_calls = 0;
  const FlippingIntegrator plant{&normalize_calls};
  adcs::sim::Rk4Integrator<FlippingIntegrator> rk4(plant, 0.1);
  FlippingIntegrator::State x(0.0);
  const Trace trace = run(plant, rk4, x, {0.0, 1.05, 0.1});

  ASSERT_EQ(trace.controller_t.size(), 11u);  // t = 0.0 .. 1.0, then the partial [1.0, 1.05]
  for (std::size_t k = 0; k < trace.controller_t.size(); ++k)
    EXPECT_EQ(trace.controller_t[k], 0.0 + static_cast<double>(k) * 0.1) << k;  // t0 + k*T
  ASSERT_EQ(trace.observer_t.size(), 12u);
  EXPECT_EQ(trace.observer_t.back(), 1.05);
  EXPECT_EQ(normalize_calls, 12);  // every sample and once at t_end
  EXPECT_EQ(rk4.time(), 1.05);

  // u holds the previous command on entry (zero at the first sample).
  EXPECT_EQ(trace.u_on_entry.front(), 0.0);
  EXPECT_EQ(trace.u_on_entry.back(), 3.0);
  EXPECT_EQ(trace.observer_u.front(), 3.0);  // the observer sees the command just computed

  // x = 3t until x > 1 at t = 0.4 (x = 1.2), flipped to -1.2 before the controller saw it.
  EXPECT_NEAR(trace.observer_x[3], 0.9, 1e-14);
  EXPECT_NEAR(trace.observer_x[4], -1.2, 1e-14);
  EXPECT_NEAR(trace.observer_x[10], -1.2 + 1.8, 1e-14);
  EXPECT_NEAR(x(0), -1.2 + 1.95, 1e-14);
  EXPECT_NEAR(trace.observer_x.back(), x(0), 0.0);
}

TEST(SampledData, WholeNumberOfPeriodsHasNoSliverInterval) {
  int normalize_calls = 0;
  const FlippingIntegrator plant{&normalize_calls};
  adcs::sim::CvodeIntegrator<FlippingIntegrator> cvode(plant);
  FlippingIntegrator::State x(-100.0);
  // 0.7 / 0.1 = 6.999999999999999 or 7.000000000000001 depending on rounding: exactly 7 samples.
  const Trace trace = run(plant, cvode, x, {2.0, 2.7, 0.1});
  ASSERT_EQ(trace.controller_t.size(), 7u);
  EXPECT_EQ(trace.controller_t.front(), 2.0);
  EXPECT_EQ(trace.controller_t.back(), 2.0 + 6 * 0.1);
  EXPECT_EQ(trace.observer_t.back(), 2.7);
  EXPECT_NEAR(x(0), -100.0 + 3.0 * 0.7, 1e-9);
}

TEST(SampledData, ZeroLengthRunObservesOnceAndInvalidOptionsThrow) {
  int normalize_calls = 0;
  const FlippingIntegrator plant{&normalize_calls};
  adcs::sim::Rk4Integrator<FlippingIntegrator> rk4(plant, 0.1);
  FlippingIntegrator::State x(5.0);
  const Trace trace = run(plant, rk4, x, {1.0, 1.0, 0.1});
  EXPECT_TRUE(trace.controller_t.empty());
  ASSERT_EQ(trace.observer_t.size(), 1u);
  EXPECT_EQ(trace.observer_u[0], 0.0);
  EXPECT_EQ(x(0), -5.0);  // normalized at t_end
  EXPECT_THROW(run(plant, rk4, x, {0.0, 1.0, 0.0}), SimError);
  EXPECT_THROW(run(plant, rk4, x, {1.0, 0.0, 0.1}), SimError);
}
