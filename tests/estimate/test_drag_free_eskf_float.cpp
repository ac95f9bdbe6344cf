// Seed 004's Algorithm 1 in float (issue 19; issue 20 asks whether the factorized filter makes
// seed 004 usable in float): DragFreeEskfT<float>, the U-D filter with its parameters rounded once
// from the double ones, on the same measurements as the double filter. It runs: every step ok,
// finite, D >= 0. What it keeps of seed 004's precision is measured per state group against the
// double filter, and the disturbance force estimate shows why the 1e-14 m s⁻²/√Hz spectrum
// claim needs double: F̂_Dsc ~ 1.3e-2 N is carried to float's 7 digits, ~1e-9 N, which on the
// 1,050-kg spacecraft is ~1e-12 m/s², about 50x the whole acceleration budget of the claim
// (1e-14 m s⁻²/√Hz over the 5-Hz band of the 10-Hz loop: 2.2e-14 m/s² rms).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "drag_free_test_params.hpp"

namespace ADCS_UNITY_ID {
using namespace adcs::test::drag_free;

//! D >= 0 and finite in both blocks' factors (PSD by construction, checked anyway).
template <class Filter>
bool factors_psd(const Filter& f) {
  const auto& d1 = f.block1().factors().D;
  const auto& d2 = f.block2().factors().D;
  return d1.allFinite() && d2.allFinite() && d1.minCoeff() >= 0.0f && d2.minCoeff() >= 0.0f;
}

}  // namespace ADCS_UNITY_ID
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

TEST(DragFreeEskfFloat, RunsOnTheDoubleFiltersDataAndLosesTheDisturbanceDigitsTheSpectrumNeeds) {
  const adcs::DragFreeParams pl;
  const adcs::DragFreeDiscrete d = discrete();
  const adcs::DragFreeEskf::Params e = eskf_params(d);
  adcs::DragFreeEskf dbl(e);
  adcs::DragFreeEskfT<float> flt(e.cast<float>());
  ASSERT_EQ(dbl.status(), Status::ok);
  ASSERT_EQ(flt.status(), Status::ok);

  std::mt19937_64 gen(21);
  std::normal_distribution<double> N01;
  const adcs::DragFreeNoise n = adcs::drag_free_noise(pl);
  adcs::Vec<27> X = adcs::Vec<27>::Zero();
  X.segment<3>(Ix::F_Dsc).setConstant(-12.8e-3);
  X.segment<3>(Ix::T_Dsc).setConstant(1e-5);
  constexpr int kSamples = 600, kSettled = 300;  // 60 s at 10 Hz; compared over the last 30 s
  adcs::Vec<27> scale = adcs::Vec<27>::Zero(), diff = adcs::Vec<27>::Zero();
  for (int k = 0; k < kSamples; ++k) {
    // The input cancels the true disturbances (as the closed loop's ADRC does, to its estimate),
    // plus noise, so the states stay at closed-loop magnitudes (nm, nrad) instead of drifting
    // open loop to metres and radians, where float's rounding of the measurements themselves
    // would decide the comparison.
    adcs::Vec<9> u;
    u << -X.segment<3>(Ix::T_Dsc), -X.segment<3>(Ix::F_Dsc), -X.segment<3>(Ix::T_Dtm);
    for (int i = 0; i < 9; ++i) u(i) += 1e-7 * N01(gen);
    if (k > 0) {
      ASSERT_EQ(dbl.predict(u), Status::ok);
      ASSERT_EQ(flt.predict(u.cast<float>()), Status::ok) << k;
      X = (d.A_d * X + d.B_d * u).eval();
    }
    adcs::Vec<9> Y = d.C_d * X;
    for (int i = 0; i < 9; ++i) Y(i) += n.sigma_pos * N01(gen);
    ASSERT_EQ(dbl.update(Y), Status::ok);
    ASSERT_EQ(flt.update(Y.cast<float>()), Status::ok) << k;
    ASSERT_TRUE(flt.state().allFinite()) << k;
    ASSERT_TRUE(factors_psd(flt)) << k;
    scale = scale.cwiseMax(dbl.state().cwiseAbs());
    if (k >= kSettled) diff = diff.cwiseMax((flt.state().cast<double>() - dbl.state()).cwiseAbs());
  }
  EXPECT_EQ(flt.psd_projections(), 0);
  // Per group, the largest difference over the last 30 s relative to the largest |x̂| of the
  // double filter over the run (each group's 3 axes).
  const struct {
    const char* name;
    int first;
  } groups[] = {{"phi_sc", Ix::phi_sc},   {"phi_sc_dot", Ix::phi_sc_dot}, {"T_Dsc", Ix::T_Dsc},
                {"r", Ix::r},             {"r_dot", Ix::r_dot},           {"F_Dsc", Ix::F_Dsc},
                {"phi_rel", Ix::phi_rel}, {"phi_rel_dot", Ix::phi_rel_dot}, {"T_Dtm", Ix::T_Dtm}};
  for (const auto& g : groups) {
    const double rel = diff.segment<3>(g.first).maxCoeff() / scale.segment<3>(g.first).maxCoeff();
    std::printf("%-12s float vs double, last 30 s: %.2e of max |x| (%.2e)\n", g.name, rel,
                scale.segment<3>(g.first).maxCoeff());
  }
  // The measured outputs (φ_sc, r_rel, φ_rel): float's estimates differ from double's by less than
  // the sensor noise σ_pos, so for what it measures the float filter is as good as its sensors.
  // The attitude block's φ_sc carries float's rounding of the largest state in its block (φ_rel,
  // ~1e-2 rad here: ulp ~1e-9 rad), the limit of float for this filter.
  std::printf("sigma_pos %.2e\n", n.sigma_pos);
  for (int first : {int(Ix::phi_sc), int(Ix::r), int(Ix::phi_rel)})
    EXPECT_LT(diff.segment<3>(first).maxCoeff(), n.sigma_pos) << first;
  // The disturbance force: float's difference from double in acceleration on the spacecraft is far
  // above the spectrum claim's whole budget (2.2e-14 m/s² rms), so seed 004's claim needs double.
  const double force_diff_accel = diff.segment<3>(Ix::F_Dsc).maxCoeff() / pl.m_sc;
  std::printf("F_Dsc float vs double: %.2e N -> %.2e m/s^2 (claim budget 2.2e-14 m/s^2 rms)\n",
              diff.segment<3>(Ix::F_Dsc).maxCoeff(), force_diff_accel);
  EXPECT_GT(force_diff_accel, 10.0 * 2.2e-14);
}

// Bad input in float: a non-finite measurement is refused with its status and the estimate kept,
// as in double (the step never hands out a non-finite estimate).
TEST(DragFreeEskfFloat, NonFiniteMeasurementIsRefusedAndTheEstimateKept) {
  const adcs::DragFreeDiscrete d = discrete();
  adcs::DragFreeEskfT<float> flt(eskf_params(d).cast<float>());
  ASSERT_EQ(flt.status(), Status::ok);
  adcs::DragFreeEskfT<float>::Input in;
  adcs::DragFreeEskfT<float>::Output out;
  ASSERT_EQ(flt.step(in, out), Status::ok);
  const adcs::Vec<27, float> before = flt.state();
  in.y(4) = NAN;
  EXPECT_EQ(flt.update(in.y), Status::non_finite_input);
  EXPECT_EQ(flt.state(), before);
  in.y(4) = 0.0f;
  in.u(2) = INFINITY;
  EXPECT_EQ(flt.predict(in.u), Status::non_finite_input);
  EXPECT_EQ(flt.state(), before);
}
