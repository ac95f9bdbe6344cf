// CvodeIntegrator and Rk4Integrator against closed-form solutions, against each other, and on
// failure. Truth for the double integrator is its exact ZOH discretisation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "sim/cvode_integrator.hpp"
#include "sim/random.hpp"
#include "sim/rk4_integrator.hpp"
#include "sim/sampled_data.hpp"

namespace ADCS_UNITY_ID {

using adcs::sim::CvodeIntegrator;
using adcs::sim::CvodeOptions;
using adcs::sim::Rk4Integrator;
using adcs::sim::SimError;

// State [p, v] (m, m/s), input a (m/s^2). With jacobian() so BDF can use it.
struct DoubleIntegrator {
  static constexpr int kStateSize = 2;
  static constexpr int kInputSize = 1;
  using State = adcs::Vec<kStateSize>;
  using Input = adcs::Vec<kInputSize>;
  void derivative(double /*t*/, const State& x, const Input& u, State& xdot) const noexcept {
    xdot << x(1), u(0);
  }
  void jacobian(double /*t*/, const State& /*x*/, const Input& /*u*/,
                adcs::Mat<2, 2>& J) const noexcept {
    J << 0.0, 1.0, 0.0, 0.0;
  }
};

// Van der Pol oscillator, mu = 1, plus the input as a forcing term; no jacobian() (BDF falls back
// to difference quotients).
struct VanDerPol {
  static constexpr int kStateSize = 2;
  static constexpr int kInputSize = 1;
  using State = adcs::Vec<kStateSize>;
  using Input = adcs::Vec<kInputSize>;
  double mu = 1.0;
  void derivative(double /*t*/, const State& x, const Input& u, State& xdot) const noexcept {
    xdot << x(1), mu * (1.0 - x(0) * x(0)) * x(1) - x(0) + u(0);
  }
};

// Derivative turns NaN after t = 0.5 s.
struct NanAfterHalfSecond {
  static constexpr int kStateSize = 1;
  static constexpr int kInputSize = 1;
  using State = adcs::Vec<kStateSize>;
  using Input = adcs::Vec<kInputSize>;
  void derivative(double t, const State& /*x*/, const Input& /*u*/, State& xdot) const noexcept {
    xdot(0) = t > 0.5 ? std::numeric_limits<double>::quiet_NaN() : 1.0;
  }
};

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

// Sophus-style explicit instantiation: every member of the templates is compiled.
template class adcs::sim::CvodeIntegrator<DoubleIntegrator>;
template class adcs::sim::CvodeIntegrator<VanDerPol>;
template class adcs::sim::Rk4Integrator<DoubleIntegrator>;
static_assert(adcs::sim::has_jacobian_v<DoubleIntegrator>);
static_assert(!adcs::sim::has_jacobian_v<VanDerPol>);
static_assert(!adcs::sim::has_normalize_v<DoubleIntegrator>);

namespace ADCS_UNITY_ID {

// Drives `integrator` through the ZOH loop with pseudo-random piecewise-constant accelerations and
// returns the largest deviation from the exact discrete solution over all samples.
template <class Integrator>
double max_error_vs_exact_zoh(Integrator& integrator) {
  const DoubleIntegrator plant;
  constexpr double kT = 0.1;  // [s]
  adcs::sim::Rng rng(2024);
  DoubleIntegrator::State x(0.3, -0.2);
  DoubleIntegrator::State exact = x;
  double max_error = 0.0;
  double a_prev = 0.0;
  adcs::sim::run_sampled_data(
      plant, integrator, x, {0.0, 5.0, kT},
      [&](double /*t*/, const DoubleIntegrator::State& /*x*/, DoubleIntegrator::Input& u) {
        u(0) = rng.uniform(-1.0, 1.0);
      },
      [&](double t, const DoubleIntegrator::State& xs, const DoubleIntegrator::Input& u) {
        if (t > 0.0) {  // propagate the exact solution over the interval that just ended
          exact(0) += exact(1) * kT + 0.5 * a_prev * kT * kT;
          exact(1) += a_prev * kT;
        }
        a_prev = u(0);
        max_error = std::max(max_error, (xs - exact).cwiseAbs().maxCoeff());
      });
  return max_error;
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

TEST(CvodeIntegrator, AdamsMatchesExactZohDoubleIntegrator) {
  const DoubleIntegrator plant;
  CvodeIntegrator<DoubleIntegrator> cvode(plant);
  EXPECT_LE(max_error_vs_exact_zoh(cvode), 1e-9);
  EXPECT_GT(cvode.steps(), 50);  // at least one step per interval, counted across re-inits
  EXPECT_DOUBLE_EQ(cvode.time(), 5.0);
}

// Why rtol = 1e-11 for BDF: at equal rtol its global error here is ~3x Adams' (measured: 1.0e-9
// at the default 1e-10, 1.0e-10 at 1e-11), because BDF's error constants are larger.
constexpr double kBdfRtol = 1e-11;

TEST(CvodeIntegrator, BdfAnalyticJacobianMatchesExactZohDoubleIntegrator) {
  const DoubleIntegrator plant;
  CvodeOptions options;
  options.method = CvodeOptions::Method::bdf_dense;
  options.rtol = kBdfRtol;
  CvodeIntegrator<DoubleIntegrator> cvode(plant, options);
  EXPECT_LE(max_error_vs_exact_zoh(cvode), 1e-9);
}

TEST(CvodeIntegrator, BdfDifferenceQuotientMatchesExactZohDoubleIntegrator) {
  const DoubleIntegrator plant;
  CvodeOptions options;
  options.method = CvodeOptions::Method::bdf_dense;
  options.rtol = kBdfRtol;
  options.analytic_jacobian = false;
  CvodeIntegrator<DoubleIntegrator> cvode(plant, options);
  EXPECT_LE(max_error_vs_exact_zoh(cvode), 1e-9);
}

TEST(Rk4Integrator, ExactOnZohDoubleIntegrator) {
  const DoubleIntegrator plant;
  Rk4Integrator<DoubleIntegrator> rk4(plant, 0.03);  // 4 substeps per 0.1 s interval
  EXPECT_LE(max_error_vs_exact_zoh(rk4), 1e-12);
  EXPECT_EQ(rk4.steps(), 50 * 4);
}

TEST(Rk4Integrator, SubstepCountIsCeilOfRatio) {
  const DoubleIntegrator plant;
  Rk4Integrator<DoubleIntegrator> rk4(plant, 0.1);
  DoubleIntegrator::State x;
  rk4.reset(0.0, DoubleIntegrator::State(0.0, 1.0));
  rk4.advance(1.0, DoubleIntegrator::Input(0.0), x);  // 1.0 / 0.1 = 10 (not 11, despite rounding)
  EXPECT_EQ(rk4.steps(), 10);
  rk4.advance(1.25, DoubleIntegrator::Input(0.0), x);  // 0.25 / 0.1 -> 3
  EXPECT_EQ(rk4.steps(), 13);
  EXPECT_EQ(rk4.time(), 1.25);
  EXPECT_NEAR(x(0), 1.25, 1e-15);
  EXPECT_THROW(rk4.advance(1.0, DoubleIntegrator::Input(0.0), x), SimError);  // backwards
  EXPECT_THROW(Rk4Integrator<DoubleIntegrator>(plant, 0.0), SimError);
}

TEST(Integrators, Rk4AndCvodeAgreeOnVanDerPol) {
  const VanDerPol plant;
  const VanDerPol::State x0(2.0, 0.0);
  const VanDerPol::Input u(0.1);
  Rk4Integrator<VanDerPol> rk4(plant, 1e-3);
  CvodeIntegrator<VanDerPol> adams(plant);
  CvodeOptions bdf_options;
  bdf_options.method = CvodeOptions::Method::bdf_dense;  // difference-quotient Jacobian
  bdf_options.rtol = kBdfRtol;
  CvodeIntegrator<VanDerPol> bdf(plant, bdf_options);
  rk4.reset(0.0, x0);
  adams.reset(0.0, x0);
  bdf.reset(0.0, x0);
  for (double t1 : {0.5, 1.0, 2.0, 3.7, 6.0, 10.0}) {
    VanDerPol::State x_rk4, x_adams, x_bdf;
    rk4.advance(t1, u, x_rk4);
    adams.advance(t1, u, x_adams);
    bdf.advance(t1, u, x_bdf);
    EXPECT_LE((x_rk4 - x_adams).cwiseAbs().maxCoeff(), 1e-8) << "t = " << t1;
    EXPECT_LE((x_rk4 - x_bdf).cwiseAbs().maxCoeff(), 1e-8) << "t = " << t1;
    EXPECT_EQ(adams.time(), t1);
  }
}

TEST(CvodeIntegrator, InputChangeWithoutResetReinitialises) {
  // advance() with a new u but no reset() must still treat the input as a step: compare with
  // the exact solution of the double integrator.
  const DoubleIntegrator plant;
  CvodeIntegrator<DoubleIntegrator> cvode(plant);
  DoubleIntegrator::State x;
  cvode.reset(0.0, DoubleIntegrator::State(0.0, 0.0));
  cvode.advance(1.0, DoubleIntegrator::Input(1.0), x);
  cvode.advance(2.0, DoubleIntegrator::Input(-1.0), x);
  EXPECT_NEAR(x(0), 1.0, 1e-9);  // 0.5 + (1 - 0.5)
  EXPECT_NEAR(x(1), 0.0, 1e-9);
  cvode.advance(2.0, DoubleIntegrator::Input(0.0), x);  // zero-length interval: no-op
  EXPECT_NEAR(x(0), 1.0, 1e-9);
}

TEST(CvodeIntegrator, TooMuchWorkThrowsNamingTheCall) {
  const VanDerPol plant;
  CvodeOptions options;
  options.max_steps = 1;
  CvodeIntegrator<VanDerPol> cvode(plant, options);
  VanDerPol::State x;
  cvode.reset(0.0, VanDerPol::State(2.0, 0.0));
  try {
    cvode.advance(100.0, VanDerPol::Input(0.0), x);
    FAIL() << "expected SimError";
  } catch (const SimError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("CVode failed: flag -1 (CV_TOO_MUCH_WORK)"), std::string::npos) << what;
  }
  EXPECT_GT(cvode.steps(), 0);
  cvode.reset(0.0, VanDerPol::State(2.0, 0.0));  // reset() after a failure is allowed
  EXPECT_EQ(cvode.time(), 0.0);
}

TEST(CvodeIntegrator, NanDerivativeThrowsNamingTheCallAndTheTime) {
  const NanAfterHalfSecond plant;
  for (const auto method : {CvodeOptions::Method::adams_fixed_point,
                            CvodeOptions::Method::bdf_dense}) {
    CvodeOptions options;
    options.method = method;
    CvodeIntegrator<NanAfterHalfSecond> cvode(plant, options);
    NanAfterHalfSecond::State x;
    cvode.reset(0.0, NanAfterHalfSecond::State(0.0));
    try {
      cvode.advance(1.0, NanAfterHalfSecond::Input(0.0), x);
      FAIL() << "expected SimError";
    } catch (const SimError& e) {
      // Fails fast (no creeping up to t = 0.5 s until CV_TOO_MUCH_WORK) and says why.
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("CVode failed: flag ", 0), 0u) << what;
      EXPECT_EQ(what.find("CV_TOO_MUCH_WORK"), std::string::npos) << what;
      EXPECT_NE(what.find("non-finite plant derivative at t = "), std::string::npos) << what;
    }
    EXPECT_LE(cvode.time(), 0.5);  // the last time reached with good derivatives
    EXPECT_LT(cvode.steps(), 1000);
    // reset() clears the failure: a run that stays before 0.5 s works.
    cvode.reset(0.0, NanAfterHalfSecond::State(0.0));
    cvode.advance(0.25, NanAfterHalfSecond::Input(0.0), x);
    EXPECT_NEAR(x(0), 0.25, 1e-12);
  }
}

TEST(CvodeIntegrator, InvalidOptionsThrowNamingTheCall) {
  const DoubleIntegrator plant;
  CvodeOptions options;
  options.rtol = -1.0;
  try {
    CvodeIntegrator<DoubleIntegrator> cvode(plant, options);
    FAIL() << "expected SimError";
  } catch (const SimError& e) {
    EXPECT_NE(std::string(e.what()).find("CVodeSStolerances failed"), std::string::npos)
        << e.what();
  }
  options = CvodeOptions{};
  options.max_step = -1.0;
  EXPECT_THROW(CvodeIntegrator<DoubleIntegrator>(plant, options), SimError);
}

TEST(CvodeIntegrator, BackwardsOrNonFiniteTimesThrow) {
  const DoubleIntegrator plant;
  CvodeIntegrator<DoubleIntegrator> cvode(plant);
  DoubleIntegrator::State x;
  cvode.reset(1.0, DoubleIntegrator::State(0.0, 0.0));
  EXPECT_THROW(cvode.advance(0.5, DoubleIntegrator::Input(0.0), x), SimError);
  EXPECT_THROW(cvode.advance(std::nan(""), DoubleIntegrator::Input(0.0), x), SimError);
  EXPECT_THROW(cvode.reset(0.0, DoubleIntegrator::State(std::nan(""), 0.0)), SimError);
}

TEST(CvodeIntegrator, MovedIntegratorKeepsWorking) {
  const DoubleIntegrator plant;
  CvodeIntegrator<DoubleIntegrator> a(plant);
  DoubleIntegrator::State x;
  a.reset(0.0, DoubleIntegrator::State(0.0, 1.0));
  a.advance(0.5, DoubleIntegrator::Input(0.0), x);
  CvodeIntegrator<DoubleIntegrator> b(std::move(a));  // CVODE's user data must follow
  b.advance(1.0, DoubleIntegrator::Input(2.0), x);
  EXPECT_NEAR(x(0), 1.0 + 0.25, 1e-9);
  CvodeIntegrator<DoubleIntegrator> c(plant);
  c = std::move(b);
  c.advance(2.0, DoubleIntegrator::Input(0.0), x);
  EXPECT_NEAR(x(0), 1.25 + 2.0, 1e-9);
  EXPECT_EQ(c.time(), 2.0);
}
