// Every controller/estimator step() (and the per-step helpers they call) with the heap
// forbidden: Eigen's runtime check aborts on any Eigen allocation, and the operator-new counter
// must read zero. Also checks the test itself is armed (asserts on, counter counting).
#ifdef NDEBUG
#error "the no-allocation test must build with asserts on (EIGEN_RUNTIME_NO_MALLOC needs them)"
#endif
#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <new>
#include <vector>

#include "adcs/adcs.hpp"
#include "alloc_guard.hpp"
#include "component_fixtures.hpp"  // tests/components: the one list of flight components
#include "counting_new.hpp"
#include "step_fixtures.hpp"  // bench/: the steps adcs-bench times

namespace ADCS_UNITY_ID {
using adcs::test::NoAllocScope;

TEST(NoMalloc, GuardIsArmed) {
  long counted = 0;
  {
    NoAllocScope scope;
    Eigen::internal::set_is_malloc_allowed(true);  // let this one through to prove counting
    // A direct call: a new-expression whose result is unused may be elided (C++14), and clang
    // -O2 without sanitizers does elide it, so the counter would prove nothing.
    void* p = ::operator new(sizeof(int));
    counted = scope.allocations();
    ::operator delete(p);
  }
  EXPECT_EQ(counted, 1);
  // And Eigen's own check fires on a dynamic allocation while forbidden.
  EXPECT_DEATH(
      {
        Eigen::internal::set_is_malloc_allowed(false);
        Eigen::MatrixXd m(10, 10);
        m.setZero();
      },
      "");
}

// Every flight component (tests/components/component_fixtures.hpp: one list) steps 100 times and
// rejects a poisoned input with the heap forbidden. A component added to the list is covered here.
template <class C>
class NoMallocComponent : public ::testing::Test {};
TYPED_TEST_SUITE(NoMallocComponent, adcs::test::FlightComponents, adcs::test::ComponentNames);

TYPED_TEST(NoMallocComponent, StepsAndRejectionsAllocateNothing) {
  using C = TypeParam;
  using Fx = adcs::test::ComponentFixture<C>;
  C c(Fx::params());  // construction may allocate (offline design: expm, Lyapunov, ...)
  ASSERT_EQ(c.status(), adcs::Status::ok);
  std::vector<typename C::Input> inputs;
  for (int k = 0; k < 100; ++k) inputs.push_back(Fx::input(k));
  typename C::Input bad = Fx::input(100);
  Fx::poison(bad);
  typename C::Output out{};
  typename C::Diagnostics diag{};
  int not_usable = 0;
  adcs::Status rejected = adcs::Status::ok;
  long allocs = 0;
  {
    NoAllocScope scope;
    for (int k = 0; k < 100; ++k) not_usable += !adcs::usable(c.step(inputs[static_cast<std::size_t>(k)], out, (k % 2) ? &diag : nullptr));
    rejected = c.step(bad, out);
    c.reset();
    allocs = scope.allocations();
  }
  EXPECT_EQ(allocs, 0);
  EXPECT_EQ(not_usable, 0);
  EXPECT_FALSE(adcs::usable(rejected));
}

// Seed 004: the ZOH discretisation (expm of a 36 x 36, construction time, fixed-size LU), then
// one full 0.1 s sample (Algorithm 1, three Algorithm 2 incl. a saturated update, three fusions,
// ADRC) repeated, and a rejected measurement.
TEST(NoMalloc, DragFreeSample) {
  const adcs::DragFreeParams p;
  adcs::DragFreeDiscrete d;
  long setup_allocs = 0;
  adcs::Status disc = adcs::Status::ok;
  {
    NoAllocScope scope;
    disc = adcs::drag_free_discretize(p, d);
    setup_allocs = scope.allocations();
  }
  ASSERT_EQ(disc, adcs::Status::ok);
  EXPECT_EQ(setup_allocs, 0);
  {  // expm<36> on every Padé degree (3, 5, 7, 9, 13 with squarings): skew generators, bounded exp
    adcs::Status st = adcs::Status::ok;
    long allocs = 0;
    {
      NoAllocScope scope;
      adcs::Mat<36, 36> A = adcs::Mat<36, 36>::Zero(), E;
      for (double c : {1e-3, 0.1, 0.45, 1.0, 2.5, 500.0}) {
        for (int i = 0; i + 1 < 36; ++i) {
          A(i, i + 1) = c;
          A(i + 1, i) = -c;
        }
        st = adcs::worst(st, adcs::expm<36>(A, E));
      }
      allocs = scope.allocations();
    }
    EXPECT_EQ(st, adcs::Status::ok);
    EXPECT_EQ(allocs, 0);
  }
  // The filters as the component list sets them up (dragfree-adrc's parameters, spec §B.8).
  const adcs::DragFreeEskf::Params e1 = adcs::test::ComponentFixture<adcs::DragFreeEskf>::params();
  adcs::DragFreeEskf a1(e1);
  const adcs::SaturatedEsfParams e2 = adcs::test::ComponentFixture<adcs::SaturatedEsf>::params();
  adcs::SaturatedEsf a2[3] = {adcs::SaturatedEsf(e2), adcs::SaturatedEsf(e2), adcs::SaturatedEsf(e2)};
  adcs::DragFreeAdrc ctrl(adcs::DragFreeAdrcParams{});
  adcs::Vec<9> u = adcs::Vec<9>::Zero(), Y = adcs::Vec<9>::Constant(1e-8);
  long allocs = 0;
  adcs::Status worst = adcs::Status::ok, rejected = adcs::Status::ok;
  {
    NoAllocScope scope;
    for (int k = 0; k < 20; ++k) {
      worst = adcs::worst(worst, a1.predict(u));
      for (auto& f : a2) worst = adcs::worst(worst, f.predict(u(3)));
      worst = adcs::worst(worst, a1.update(Y));
      const adcs::Vec3 F(a2[0].state()(2), a2[1].state()(2), a2[2].state()(2));
      adcs::DragFreeActuation act;
      worst = adcs::worst(worst, ctrl.step(adcs::DragFreeAdrcInput{a1.state(), F, adcs::Vec3::Zero()}, act));
      u = act.stacked();
      for (int j = 0; j < 3; ++j) {
        worst = adcs::worst(worst, a2[j].update(k % 2 ? 6e-6 : 1e-7, u(3 + j)));
        worst = adcs::worst(worst, adcs::fuse_axis(a1, a2[j], j));
      }
    }
    // The PSD projection fallback (eigen-decomposition) must be heap-free too.
    adcs::Mat<27, 27> P_bad = adcs::Mat<27, 27>::Identity();
    P_bad(0, 0) = -1e-3;
    if (!adcs::keep_psd<27>(P_bad)) worst = adcs::Status::out_of_range;
    Y(3) = std::numeric_limits<double>::quiet_NaN();
    rejected = a1.update(Y);
    allocs = scope.allocations();
  }
  EXPECT_EQ(allocs, 0);
  EXPECT_TRUE(adcs::usable(worst)) << adcs::to_string(worst);
  EXPECT_EQ(rejected, adcs::Status::non_finite_input);
}

TEST(NoMalloc, PlantDerivativeAndMathKernels) {
  adcs::RigidBodyRwParams<4> pp;
  pp.J_B = adcs::Vec3(900, 800, 600).asDiagonal();
  pp.G_s_B = adcs::test::four_wheel_axes();
  pp.J_s.setConstant(0.1);
  adcs::RigidBodyRw<4> plant(pp);
  adcs::RigidBodyRw<4>::State x = adcs::RigidBodyRw<4>::State::Constant(0.1);
  adcs::RigidBodyRw<4>::State xdot;
  adcs::RigidBodyRw<4>::Input u = adcs::RigidBodyRw<4>::Input::Constant(0.01);
  adcs::Mat<3, 7> X = adcs::Mat<3, 7>::Random();
  adcs::Vec3 v(1, 2, 3);
  adcs::Vec<7> u7;
  adcs::Mat6 A1, P;
  adcs::Mat<3, 6> K;
  const adcs::AxisPoles<3> poles{{{{{-0.2, 0.2}, {-0.2, -0.2}}},
                                  {{{-0.3, 0.3}, {-0.3, -0.3}}},
                                  {{{-0.2 * std::sqrt(2.0), 0}, {-0.3 * std::sqrt(2.0), 0}}}}};
  long allocs = 0;
  adcs::Status s[8];
  adcs::VscmgGeometry<4, 0> cmgs;
  ASSERT_EQ(adcs::set_cmg_pyramid(1.0, 0.03, cmgs), adcs::Status::ok);
  adcs::Vec<4> u4;
  {
    NoAllocScope scope;
    plant.derivative(0.0, x, u, xdot);
    s[0] = adcs::right_pinv_solve<3, 7>(X, v, u7);
    adcs::PinvInfo info;
    s[1] = adcs::damped_right_pinv_solve<3, 7>(X, v, u7, {}, &info);
    // Set-up kernels are not per-step, but they are fixed-size too: prove it.
    s[2] = adcs::place_double_integrator<3>(poles, K);
    A1 = adcs::double_integrator_closed_loop<3>(K);
    s[3] = adcs::solve_continuous_lyapunov<6>(A1, adcs::Mat6::Identity(), P);
    // Per-step kernels of the adaptive laws (seed 001): projection, safeguard, steering.
    adcs::Vec<6> th = adcs::Vec<6>::Constant(0.2), dth;
    s[4] = adcs::smooth_projection<6>(th, adcs::Vec<6>::Ones(), adcs::ProjectionParams{}, dth);
    (void)adcs::radial_safeguard<6>(th, 0.15);
    s[5] = adcs::usable(adcs::steer<7>(X, v, adcs::SteeringParams{}, u7)) ? adcs::Status::ok
                                                                        : adcs::Status::singular;
    const adcs::SinusoidalRateReference ref;
    const adcs::MrpReferenceSample rs = ref.sample(12.0, v * 0.1);
    s[6] = adcs::all_finite(rs.sigma_ddot) ? adcs::Status::ok : adcs::Status::non_finite_input;
    // The singularity-escape steering of a pure CMG cluster (issue 15).
    s[7] = adcs::steer_escape<4>(cmgs.A_ct(adcs::Vec<4>::Constant(0.1)) * cmgs.h_cw.asDiagonal(),
                                 adcs::Vec3(1e-3, 0.0, 0.0), adcs::EscapeSteeringParams{}, 0.3, u4);
    // The seed 001 truth plant's right-hand side (run inside CVODE's callback).
    static const adcs::VscmgFullPlant<4, 3> vscmg(adcs::vscmg_params_A_REF());
    adcs::VscmgFullPlant<4, 3>::State xv = adcs::VscmgFullPlant<4, 3>::State::Constant(0.05), xvd;
    vscmg.derivative(0.0, xv, adcs::VscmgFullPlant<4, 3>::Input::Constant(1e-3), xvd);
    allocs = scope.allocations();
  }
  EXPECT_EQ(allocs, 0);
  for (adcs::Status st : s) EXPECT_EQ(st, adcs::Status::ok);
}
// Every step adcs-bench times (bench/step_fixtures.hpp: each controller, estimator, the seed 004
// sample and the quantizer) 100 times with the heap forbidden: the budget checker's
// allocs_per_step = 0 is proven here with Eigen's runtime check as well.
template <class Fixture>
long allocations_of_100_steps() {
  Fixture step;  // construction may allocate (offline design: expm, Lyapunov, ...)
  step();
  NoAllocScope guard;
  for (int k = 0; k < 100; ++k) step();
  return guard.allocations();
}

TEST(NoMalloc, EveryBenchmarkedStep) {
  namespace fx = adcs::bench;
  EXPECT_EQ(allocations_of_100_steps<fx::MrpPdStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::RwAllocationStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::HybridAdaptiveStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::HybridAdaptiveNormalizedStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::FlexiblePPCStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::AdaptiveTrackingStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::DragFreeEskfStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::SaturatedEsfStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::FusionStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::AdrcStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::PidStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::DragFreeAdrcStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::SE3PrescribedTimeStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::SE3FtsmcStep>(), 0);
  EXPECT_EQ(allocations_of_100_steps<fx::CompositeQuantizerStep>(), 0);
}

}  // namespace ADCS_UNITY_ID
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  return RUN_ALL_TESTS();
}
