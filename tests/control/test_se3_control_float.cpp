// Issue 19: seed 003 in single precision. The SE(3) coefficients, the error kinematics and both
// laws (PrescribedTimeSe3T<float>, FtsmcSe3T<float>) against their double instances, and the
// failure paths in float.
//
// How the comparisons are made. A float law reads its input rounded to float, and in seed 003
// that rounding is the dominant error: the ECI positions (~6.8e6 m) carry 0.5 m and the inertial
// velocities (~7.7 km/s) 4.9e-4 m/s (the scenario's steady position error in float, 2-6 mm,
// comes from there: docs/TARGET.md). That is a property of the input, not of the arithmetic, so
// the law comparisons feed the double law the SAME rounded input (cast back to double, exact):
// what is left is the float arithmetic alone. Its bound is relative to the largest term that
// enters the command (the nominal drift F0 is gravity and ω×v, ~8.7 m/s², cancelling against
// the desired acceleration to ~1e-5 m/s²; the float result is good to ~1e-7 of the terms, not
// of the small difference).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/math/se3.hpp"
#include "scenarios/seed003_data.hpp"  // seed 003's scenario data (paper data, not flight code)

namespace ADCS_UNITY_ID {
using adcs::Status;

constexpr double kPi = 3.14159265358979323846;

// |a − b| / max(|b|, floor): relative error with an absolute floor.
double rel(double a, double b, double floor) { return std::fabs(a - b) / std::fmax(std::fabs(b), floor); }

// The φ-coefficients in float against double over the whole log chart φ ∈ [0, π]: the float
// switches (exp_coord_series_switch_v<float> = 1, gamma_rate_series_switch_v<float> = 3, γ's long
// series below kGammaFloatSeriesSwitch = 2) keep
// every coefficient to a few 1e-6 relative; at double's switches γ's float closed form would be
// off by O(1) at φ = 0.05 (1e3 ε/φ⁴).
TEST(Se3Float, ExpCoordCoefficientsHoldFloatAccuracyOverTheLogChart) {
  double worst[6] = {0, 0, 0, 0, 0, 0};
  for (int i = 0; i <= 4000; ++i) {
    const double phi = kPi * i / 4000.0;
    const float phif = static_cast<float>(phi);
    const adcs::Se3ExpCoordCoefficientsT<float> f = adcs::se3_exp_coord_coefficients(phif);
    // The double reference at the same (rounded) φ.
    const adcs::Se3ExpCoordCoefficients d = adcs::se3_exp_coord_coefficients(static_cast<double>(phif));
    const double e[6] = {rel(f.one_minus_cos, d.one_minus_cos, 0), rel(f.phi_minus_sin, d.phi_minus_sin, 0),
                         rel(f.alpha, d.alpha, 0),                 rel(f.gamma, d.gamma, 0),
                         rel(f.gamma_rate, d.gamma_rate, 0),       0.0};
    for (int j = 0; j < 5; ++j) worst[j] = std::fmax(worst[j], e[j]);
    // The single functions agree with the one-pass coefficients in float too.
    EXPECT_LE(rel(adcs::se3_gamma(phif), d.gamma, 0), 2e-5) << phi;
    EXPECT_LE(rel(adcs::se3_alpha(phif), d.alpha, 0), 2e-5) << phi;
  }
  std::printf("float/double worst relative: (1-cos)/phi^2 %.2e, (phi-sin)/phi^3 %.2e, alpha %.2e, gamma %.2e, "
              "gamma'/phi %.2e\n", worst[0], worst[1], worst[2], worst[3], worst[4]);
  EXPECT_LE(worst[0], 2e-6);
  EXPECT_LE(worst[1], 2e-6);
  EXPECT_LE(worst[2], 1e-5);
  EXPECT_LE(worst[3], 2e-5);  // γ: the closed form at φ ≥ 2
  EXPECT_LE(worst[4], 2e-5);
  static_assert(adcs::exp_coord_series_switch_v<double> == adcs::kExpCoordSeriesSwitch);
  static_assert(adcs::gamma_rate_series_switch_v<double> == adcs::kGammaRateSeriesSwitch);
}

// A random relative pose (rotation up to `max_angle`, position up to `max_pos` m) and twist.
struct RandomPose {
  std::mt19937 rng{20261128};
  std::uniform_real_distribution<double> u{-1.0, 1.0};
  adcs::Vec3 vec(double s) { return adcs::Vec3(s * u(rng), s * u(rng), s * u(rng)); }
};

// The error kinematics in float against double on the same rounded relative pose and twist
// (no ECI positions here: the pose is relative, so only the arithmetic differs).
TEST(Se3Float, ErrorKinematicsMatchDoubleOnRelativePoses) {
  RandomPose r;
  double worst = 0.0;
  for (int k = 0; k < 500; ++k) {
    const double angle = (k % 5 == 0) ? 3.0 : 1.0;  // every fifth pose near the end of the chart
    adcs::Se3T<float> gf{adcs::so3_exp(adcs::Vec<3, float>(r.vec(angle).cast<float>())),
                         r.vec(30.0).cast<float>()};
    const adcs::Vec<6, float> xif = adcs::stack3(r.vec(0.02).cast<float>(), r.vec(0.5).cast<float>());
    const adcs::Se3 gd{gf.C.cast<double>(), gf.R.cast<double>()};
    const adcs::Se3ErrorKinematicsT<float> f = adcs::se3_error_kinematics(gf, xif);
    const adcs::Se3ErrorKinematics d = adcs::se3_error_kinematics(gd, adcs::Vec6(xif.cast<double>()));
    // Relative to the size of each quantity (η ~ 30 m, η̇ ~ 0.5 m/s).
    worst = std::fmax(worst, (f.eta.cast<double>() - d.eta).norm() / d.eta.norm());
    worst = std::fmax(worst, (f.eta_dot.cast<double>() - d.eta_dot).norm() / d.eta_dot.norm());
    worst = std::fmax(worst, (f.G.matrix().cast<double>() - d.G.matrix()).norm() / d.G.matrix().norm());
    worst = std::fmax(worst, (f.G.inverse_matrix().cast<double>() - d.G.inverse_matrix()).norm() /
                                 d.G.inverse_matrix().norm());
    worst = std::fmax(worst, (f.G_dot_xi.cast<double>() - d.G_dot_xi).norm() / std::fmax(d.G_dot_xi.norm(), 1e-3));
  }
  std::printf("error kinematics float/double worst relative: %.2e\n", worst);
  EXPECT_LE(worst, 2e-5);
}

// Seed 003's chaser/target pair at an initial state, the desired state from the target model, and
// a perturbed relative twist (so every term of the laws is active).
adcs::Se3TrackingInput paper_input(int state, RandomPose& r) {
  const adcs::Vec3 d_omega = r.vec(5e-3);  // drawn in this order (argument order is unspecified)
  const adcs::Vec3 d_v = r.vec(0.2);
  adcs::Se3TrackingInput in;
  EXPECT_TRUE(adcs::se3_paper_tracking_input(adcs::Se3ScenarioParams{}, state, d_omega, d_v, in.state, in.desired));
  return in;
}

adcs::PrescribedTimeSe3Params ptc_params_d() {
  adcs::PrescribedTimeSe3Params p;
  p.zeta = adcs::quantization_compensation_gain(adcs::seed003_quantizer_params());
  p.nominal = adcs::se3_chaser_nominal_params(adcs::Se3ScenarioParams{});
  return p;
}
adcs::FtsmcSe3Params ftsmc_params_d() {
  adcs::FtsmcSe3Params p;
  p.nominal = adcs::se3_chaser_nominal_params(adcs::Se3ScenarioParams{});
  return p;
}

// Both laws, float against double on the same float-rounded input, 200 ticks from each of the
// paper's four initial states (the laws keep state: ψ̂, the last command). Bound: 2e-3 of the
// largest command component of the tick, or of 1 N (N m). The float arithmetic's largest error is
// in the relative velocity v_e = v − C_eᵀ(v_d − R_e × ω_d), formed from inertial velocities of
// ~7.7 km/s: ε·|v| ≈ 4.6e-4 m/s of a v_e of ~0.2 m/s, times Ξ0 (105 kg) and the gains (K3 = 0.5,
// the shaping terms): ~0.03-0.05 N of commands of ~50-100 N (measured 5.2e-4 BsPdTC, 3.4e-4
// FTSMC). A constant rounded through the wrong type or a wrong term gives O(1e-2) and more.
template <class LawF, class LawD>
double worst_law_error(const typename LawD::Params& pd, const char* what) {
  RandomPose r;
  double worst = 0.0;
  for (int state = 0; state < 4; ++state) {
    LawF lf(pd.template cast<float>());
    LawD ld(pd);
    EXPECT_EQ(lf.status(), Status::ok);
    EXPECT_EQ(ld.status(), Status::ok);
    for (int k = 0; k < 200; ++k) {
      const adcs::Se3TrackingInputT<float> inf = paper_input(state, r).template cast<float>();
      const adcs::Se3TrackingInput ind = inf.template cast<double>();  // exact
      typename LawF::Output of;
      adcs::Wrench od;
      EXPECT_EQ(lf.step(inf, of), Status::ok);
      EXPECT_EQ(ld.step(ind, od), Status::ok);
      const adcs::Vec6 uf = of.stacked().template cast<double>(), ud = od.stacked();
      const double scale = std::fmax(ud.cwiseAbs().maxCoeff(), 1.0);
      worst = std::fmax(worst, (uf - ud).cwiseAbs().maxCoeff() / scale);
      EXPECT_TRUE(adcs::all_finite(uf));
    }
  }
  std::printf("%s float/double worst command error (same rounded input): %.2e of max(|u|, 1)\n", what, worst);
  return worst;
}

TEST(Se3Float, PrescribedTimeLawMatchesDoubleOnTheSameRoundedInput) {
  EXPECT_LE((worst_law_error<adcs::PrescribedTimeSe3T<float>, adcs::PrescribedTimeSe3>(ptc_params_d(), "BsPdTC")),
            2e-3);
}

TEST(Se3Float, FtsmcLawMatchesDoubleOnTheSameRoundedInput) {
  EXPECT_LE((worst_law_error<adcs::FtsmcSe3T<float>, adcs::FtsmcSe3>(ftsmc_params_d(), "FTSMC")), 2e-3);
}

// Why float is not enough for seed 003's positions: one float ulp of an ECI coordinate at 400 km
// altitude is 0.5 m, against the 1e-4 m settling band of spec A.9 (the law reads R − R_d as the
// difference of two such numbers). A unit test of the number the docs quote.
TEST(Se3Float, EciPositionUlpIsHalfAMetre) {
  const float R = static_cast<float>(6378e3 + 400e3);
  EXPECT_EQ(std::nextafter(R, std::numeric_limits<float>::infinity()) - R, 0.5f);
  const float V = 7.67e3f;  // circular speed at 400 km [m/s]
  EXPECT_EQ(std::nextafter(V, std::numeric_limits<float>::infinity()) - V, 0x1p-11f);  // 4.9e-4 m/s
}

// Failure paths in float: a NaN input gives non_finite_input, the zero wrench (safe_command) and
// ψ̂ unchanged; an input beyond float's range (narrowed to Inf) is refused the same way; a
// parameter beyond float's range is refused at construction.
TEST(Se3Float, BadInputAndParametersAreRefusedInFloat) {
  RandomPose r;
  adcs::PrescribedTimeSe3T<float> law(ptc_params_d().cast<float>());
  ASSERT_EQ(law.status(), Status::ok);
  const adcs::Se3TrackingInputT<float> good = paper_input(1, r).cast<float>();
  adcs::WrenchT<float> out;
  ASSERT_EQ(law.step(good, out), Status::ok);
  const float psi = law.psi_hat();
  adcs::Se3TrackingInputT<float> bad = good;
  bad.state.omega_BN_B(1) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(law.step(bad, out), Status::non_finite_input);
  EXPECT_EQ(out.stacked(), (adcs::Vec<6, float>::Zero()));
  EXPECT_EQ(law.psi_hat(), psi);
  adcs::Se3TrackingInput huge = paper_input(1, r);
  huge.desired.v_dot_D(0) = 1e300;  // beyond float: narrowed to +Inf by cast<float>()
  EXPECT_EQ(law.step(huge.cast<float>(), out), Status::non_finite_input);
  EXPECT_EQ(out.stacked(), (adcs::Vec<6, float>::Zero()));
  EXPECT_EQ(law.psi_hat(), psi);

  adcs::PrescribedTimeSe3Params p = ptc_params_d();
  p.sigma2 = 1e60;  // finite in double, +Inf in float
  EXPECT_EQ(adcs::PrescribedTimeSe3(p).status(), Status::ok);
  EXPECT_EQ(adcs::PrescribedTimeSe3T<float>(p.cast<float>()).status(), Status::invalid_parameter);
  adcs::FtsmcSe3Params q = ftsmc_params_d();
  q.nominal.m = 1e40;  // a mass beyond float's range
  EXPECT_EQ(adcs::FtsmcSe3T<float>(q.cast<float>()).status(), Status::invalid_parameter);
}

}  // namespace ADCS_UNITY_ID
