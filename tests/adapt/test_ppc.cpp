// Prescribed-performance error transform (ppc.hpp), seed 002 spec §B.3 steps 2-7 and §B.7:
// B-S7 (S/S⁻¹ round trip, finiteness iff inside, ε_z > 0, finite-difference ε_z and ε_zz,
// S(0) = ±½ for δ = 0), B-S8 (ε̇ = r q, ṙ and q̇ = ë + q_dot_offset against finite differences
// along a trajectory inside the funnel), B-S10 (performance function, init() branches and
// feasibility), plus funnel-edge handling (out_of_range / robust clamp) and bad input.
// Scenario values from spec §B.5: ρ0 = 0.3°, ρ∞ = 0.005°, k = 0.15 1/s, δ = 0,
// e(0) = [0.25, 0.15, −0.20]°, all in radians here.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "adcs/adapt/ppc.hpp"

namespace ADCS_UNITY_ID {
using adcs::PerformanceFunction;
using adcs::PpcBranch;
using adcs::PpcInverse;
using adcs::Status;
using V3 = adcs::Vec<3>;
using Ppc = adcs::PrescribedPerformance<3>;

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

const PerformanceFunction kRho{0.3 * kDeg, 0.005 * kDeg, 0.15};  // spec §B.5 Table 2
const V3 kE0 = V3(0.25, 0.15, -0.20) * kDeg;                       // spec §B.5, b = (+, +, −)

Ppc::Params scenario_params(double delta = 0.0, bool robust = false) {
  Ppc::Params p;
  p.rho.fill(kRho);
  p.delta = V3::Constant(delta);
  p.robust_clamp = robust;
  return p;
}

// Edges of the open interval of eq. (6).
double lower_edge(PpcBranch b, double delta) { return b == PpcBranch::positive ? -delta : -1.0; }
double upper_edge(PpcBranch b, double delta) { return b == PpcBranch::positive ? 1.0 : delta; }

PpcInverse inverse(double z, PpcBranch b, double delta) {
  PpcInverse out;
  EXPECT_EQ(adcs::ppc_S_inverse(z, b, delta, out), Status::ok) << "z = " << z;
  return out;
}

Ppc::Sample sentinel_sample() {
  Ppc::Sample s;
  for (V3* v : {&s.rho, &s.rho_dot, &s.rho_ddot, &s.z, &s.eps, &s.eps_dot, &s.r, &s.r_dot, &s.q,
                &s.q_dot_offset})
    *v = V3::Constant(42.0);
  s.margin_min = 42.0;
  return s;
}

bool is_sentinel(const Ppc::Sample& s) {
  const Ppc::Sample t = sentinel_sample();
  return s.rho == t.rho && s.rho_dot == t.rho_dot && s.rho_ddot == t.rho_ddot && s.z == t.z &&
         s.eps == t.eps && s.eps_dot == t.eps_dot && s.r == t.r && s.r_dot == t.r_dot &&
         s.q == t.q && s.q_dot_offset == t.q_dot_offset && s.margin_min == t.margin_min;
}

bool all_fields_finite(const Ppc::Sample& s) {
  return adcs::all_finite(s.rho) && adcs::all_finite(s.rho_dot) && adcs::all_finite(s.rho_ddot) &&
         adcs::all_finite(s.z) && adcs::all_finite(s.eps) && adcs::all_finite(s.eps_dot) &&
         adcs::all_finite(s.r) && adcs::all_finite(s.r_dot) && adcs::all_finite(s.q) &&
         adcs::all_finite(s.q_dot_offset) && std::isfinite(s.margin_min);
}

struct BranchCase {
  PpcBranch b;
  double delta;
};
const std::vector<BranchCase> kCases{{PpcBranch::positive, 0.0},
                                     {PpcBranch::negative, 0.0},
                                     {PpcBranch::positive, 0.3},
                                     {PpcBranch::negative, 0.3}};

// ---------------------------------------------------------------------------------- B-S7

TEST(PpcTransform, ForwardMapInvertsTheInverseOnBothBranches) {  // spec B-S7, eqs. (7), (9)
  for (const BranchCase& c : kCases) {
    const double lo = lower_edge(c.b, c.delta), hi = upper_edge(c.b, c.delta);
    for (int k = 1; k < 400; ++k) {
      const double z = lo + (hi - lo) * k / 400.0;
      const PpcInverse inv = inverse(z, c.b, c.delta);
      EXPECT_TRUE(std::isfinite(inv.eps));
      EXPECT_NEAR(adcs::ppc_S(inv.eps, c.b, c.delta), z, 1e-14) << z;
    }
    // Right next to both edges as well (ε large in magnitude, still invertible).
    for (double gap : {1e-3, 1e-6, 1e-9}) {
      EXPECT_NEAR(adcs::ppc_S(inverse(hi - gap, c.b, c.delta).eps, c.b, c.delta), hi - gap, 1e-13);
      EXPECT_NEAR(adcs::ppc_S(inverse(lo + gap, c.b, c.delta).eps, c.b, c.delta), lo + gap, 1e-13);
    }
  }
}

TEST(PpcTransform, InverseOfForwardMapIsIdentityInEpsilon) {  // spec B-S7
  for (const BranchCase& c : kCases)
    for (double eps = -8.0; eps <= 8.0; eps += 0.25)
      EXPECT_NEAR(inverse(adcs::ppc_S(eps, c.b, c.delta), c.b, c.delta).eps, eps,
                  1e-13 + 1e-15 * std::exp(2 * std::abs(eps)));  // S loses ~e^{-2|ε|} near an edge
}

TEST(PpcTransform, ForwardMapTendsToTheIntervalEdges) {  // spec B.4-#6 (Property 3)
  for (const BranchCase& c : kCases) {
    EXPECT_NEAR(adcs::ppc_S(40.0, c.b, c.delta), upper_edge(c.b, c.delta), 1e-15);
    EXPECT_NEAR(adcs::ppc_S(-40.0, c.b, c.delta), lower_edge(c.b, c.delta), 1e-15);
  }
}

TEST(PpcTransform, EpsilonFiniteOnlyStrictlyInsideAndOutputUntouchedOtherwise) {  // spec B-S7
  for (const BranchCase& c : kCases) {
    const double lo = lower_edge(c.b, c.delta), hi = upper_edge(c.b, c.delta);
    // Strictly inside, even one ulp from a nonzero edge, or 1e-150 from an edge at z = 0: ok and
    // finite. Closer to a zero edge 1/distance² overflows: that is the edge numerically, and
    // ppc_S_inverse says out_of_range rather than return Inf (checked below).
    EXPECT_TRUE(std::isfinite(inverse(hi == 0.0 ? -1e-150 : std::nextafter(hi, -kInf), c.b, c.delta).eps));
    EXPECT_TRUE(std::isfinite(inverse(lo == 0.0 ? 1e-150 : std::nextafter(lo, kInf), c.b, c.delta).eps));
    for (double z : {hi == 0.0 ? -1e-160 : hi, lo == 0.0 ? 1e-160 : lo}) {
      PpcInverse out{42.0, 43.0, 44.0};
      EXPECT_EQ(adcs::ppc_S_inverse(z, c.b, c.delta, out), Status::out_of_range) << z;
      EXPECT_EQ(out.eps_zz, 44.0);
    }
    // At the robust-clamp distance the derivatives are finite too. (Much closer to an edge at
    // z = 0 they overflow: 1/(distance)² is Inf below ~1.5e-154; not a physical regime.)
    for (double z : {hi - Ppc::kClampMargin, lo + Ppc::kClampMargin}) {
      const PpcInverse inv = inverse(z, c.b, c.delta);
      EXPECT_TRUE(std::isfinite(inv.eps) && std::isfinite(inv.eps_z) && std::isfinite(inv.eps_zz)) << z;
    }
    // On or beyond an edge: out_of_range, output untouched (so never NaN/Inf).
    for (double z : {hi, lo, std::nextafter(hi, kInf), std::nextafter(lo, -kInf), hi + 0.5, lo - 0.5,
                     1e300, -1e300}) {
      PpcInverse out{42.0, 43.0, 44.0};
      EXPECT_EQ(adcs::ppc_S_inverse(z, c.b, c.delta, out), Status::out_of_range) << z;
      EXPECT_EQ(out.eps, 42.0);
      EXPECT_EQ(out.eps_z, 43.0);
      EXPECT_EQ(out.eps_zz, 44.0);
      EXPECT_LE(adcs::ppc_margin(z, c.b, c.delta), 0.0) << z;
    }
    for (double z : {kNaN, kInf, -kInf}) {
      PpcInverse out{42.0, 43.0, 44.0};
      EXPECT_EQ(adcs::ppc_S_inverse(z, c.b, c.delta, out), Status::non_finite_input);
      EXPECT_EQ(out.eps, 42.0);
      EXPECT_EQ(out.eps_z, 43.0);
      EXPECT_EQ(out.eps_zz, 44.0);
    }
  }
}

TEST(PpcTransform, EpsilonGrowsWithoutBoundTowardsTheEnds) {  // spec B-S7 (ε → ±∞ at the ends)
  for (const BranchCase& c : kCases) {
    const double lo = lower_edge(c.b, c.delta), hi = upper_edge(c.b, c.delta);
    double prev_up = -kInf, prev_down = kInf;
    for (int k = 1; k <= 12; ++k) {
      const double gap = std::pow(10.0, -k);
      const double up = inverse(hi - gap, c.b, c.delta).eps;
      const double down = inverse(lo + gap, c.b, c.delta).eps;
      EXPECT_GT(up, prev_up);
      EXPECT_LT(down, prev_down);
      // |ε| ≈ ½ |ln(gap)| + const, so it grows by ½ ln 10 ≈ 1.15 per decade close to the edge.
      if (k > 2) {
        EXPECT_NEAR(up - prev_up, 0.5 * std::log(10.0), 1e-2);
        EXPECT_NEAR(prev_down - down, 0.5 * std::log(10.0), 1e-2);
      }
      prev_up = up;
      prev_down = down;
    }
    EXPECT_GT(prev_up, 13.0);
    EXPECT_LT(prev_down, -13.0);
  }
}

TEST(PpcTransform, DerivativesOfTheInverseMatchFiniteDifferences) {  // spec B-S7, §B.3 step 5
  const double h = 1e-5;
  for (const BranchCase& c : kCases) {
    const double lo = lower_edge(c.b, c.delta), hi = upper_edge(c.b, c.delta);
    for (int k = 0; k <= 50; ++k) {
      const double z = lo + 0.02 + (hi - lo - 0.04) * k / 50.0;
      const PpcInverse m = inverse(z - h, c.b, c.delta), o = inverse(z, c.b, c.delta),
                       p = inverse(z + h, c.b, c.delta);
      EXPECT_GT(o.eps_z, 0.0);
      const double fd_z = (p.eps - m.eps) / (2 * h);
      const double fd_zz = (p.eps_z - m.eps_z) / (2 * h);
      const double fd2_zz = (p.eps - 2 * o.eps + m.eps) / (h * h);
      EXPECT_NEAR(o.eps_z, fd_z, 1e-6 * o.eps_z) << z;
      EXPECT_NEAR(o.eps_zz, fd_zz, 1e-6 * (std::abs(o.eps_zz) + o.eps_z)) << z;
      EXPECT_NEAR(o.eps_zz, fd2_zz, 1e-4 * (std::abs(o.eps_zz) + o.eps_z)) << z;
      // Closed form of spec §B.3 step 5: ε_z = ½(1 + δ)/(distance to lower · distance to upper).
      EXPECT_NEAR(o.eps_z, 0.5 * (1 + c.delta) / ((z - lo) * (hi - z)), 1e-12 * o.eps_z);
    }
  }
}

TEST(PpcTransform, ZeroDeltaCentresTheFunnelAtPlusMinusHalf) {  // spec B-S7, B.4-#15(b)
  EXPECT_DOUBLE_EQ(adcs::ppc_S(0.0, PpcBranch::positive, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(adcs::ppc_S(0.0, PpcBranch::negative, 0.0), -0.5);
  EXPECT_DOUBLE_EQ(inverse(0.5, PpcBranch::positive, 0.0).eps, 0.0);
  EXPECT_DOUBLE_EQ(inverse(-0.5, PpcBranch::negative, 0.0).eps, 0.0);
  // General δ: ε = 0 ↔ z = ±(1 − δ)/2.
  EXPECT_NEAR(adcs::ppc_S(0.0, PpcBranch::positive, 0.3), 0.35, 1e-15);
  EXPECT_NEAR(adcs::ppc_S(0.0, PpcBranch::negative, 0.3), -0.35, 1e-15);
}

// ---------------------------------------------------------------------------------- B-S10

TEST(PpcPerformanceFunction, StartsAtRho0DecaysMonotonicallyToRhoInf) {  // spec B-S10, eq. (5)
  const adcs::PerformanceSample s0 = adcs::evaluate(kRho, 0.0);
  EXPECT_NEAR(s0.rho, kRho.rho0, 1e-18);
  EXPECT_NEAR(s0.rho_dot, -kRho.k * (kRho.rho0 - kRho.rho_inf), 1e-18);
  EXPECT_NEAR(s0.rho_ddot, kRho.k * kRho.k * (kRho.rho0 - kRho.rho_inf), 1e-18);
  EXPECT_NEAR(adcs::evaluate(kRho, 300.0).rho, kRho.rho_inf, 1e-12 * kRho.rho_inf);
  // Spec §B.5: ρ(40 s) = 0.0057°.
  EXPECT_NEAR(adcs::evaluate(kRho, 40.0).rho / kDeg, 0.0057, 5e-5);
  double prev = kInf;
  const double h = 1e-3;
  for (double t = 0.0; t <= 100.0; t += 0.5) {
    const adcs::PerformanceSample s = adcs::evaluate(kRho, t);
    EXPECT_LT(s.rho, prev);
    EXPECT_GT(s.rho, kRho.rho_inf);
    EXPECT_LT(s.rho_dot, 0.0);
    EXPECT_GT(s.rho_ddot, 0.0);
    const adcs::PerformanceSample m = adcs::evaluate(kRho, t + h), p = adcs::evaluate(kRho, t - h);
    EXPECT_NEAR(s.rho_dot, (m.rho - p.rho) / (2 * h), 1e-7 * std::abs(s.rho_dot)) << t;
    EXPECT_NEAR(s.rho_ddot, (m.rho_dot - p.rho_dot) / (2 * h), 1e-7 * s.rho_ddot) << t;
    prev = s.rho;
  }
}

TEST(PpcPerformanceFunction, InvalidParametersAreRejected) {
  EXPECT_TRUE(adcs::valid(kRho));
  for (const PerformanceFunction& f :
       {PerformanceFunction{0.1, 0.1, 1.0}, PerformanceFunction{0.1, 0.2, 1.0},
        PerformanceFunction{0.1, 0.0, 1.0}, PerformanceFunction{0.1, 0.01, 0.0},
        PerformanceFunction{0.1, 0.01, -1.0}, PerformanceFunction{kNaN, 0.01, 1.0},
        PerformanceFunction{kInf, 0.01, 1.0}}) {
    EXPECT_FALSE(adcs::valid(f));
    Ppc::Params p = scenario_params();
    p.rho[1] = f;
    const Ppc ppc(p);
    EXPECT_EQ(ppc.status(), Status::invalid_parameter);
  }
  for (double delta : {-0.1, 1.1, kNaN}) {
    Ppc::Params p = scenario_params();
    p.delta(2) = delta;
    Ppc ppc(p);
    EXPECT_EQ(ppc.status(), Status::invalid_parameter);
    EXPECT_EQ(ppc.init(kE0), Status::invalid_parameter);
    Ppc::Sample out = sentinel_sample();
    EXPECT_EQ(ppc.transform(1.0, kE0, V3::Zero(), out), Status::invalid_parameter);
    EXPECT_TRUE(is_sentinel(out));
  }
  EXPECT_EQ(Ppc(scenario_params(1.0)).status(), Status::ok);  // δ ∈ [0, 1] inclusive
}

TEST(PpcInit, ScenarioErrorGivesBranchesPlusPlusMinus) {  // spec B-S10, §B.3 "fixed at t = 0"
  Ppc ppc(scenario_params());
  ASSERT_EQ(ppc.status(), Status::ok);
  EXPECT_EQ(ppc.init(kE0), Status::ok);
  EXPECT_EQ(ppc.branch(0), PpcBranch::positive);
  EXPECT_EQ(ppc.branch(1), PpcBranch::positive);
  EXPECT_EQ(ppc.branch(2), PpcBranch::negative);
  // Re-init with flipped signs flips the branches.
  EXPECT_EQ(ppc.init(-kE0), Status::ok);
  EXPECT_EQ(ppc.branch(0), PpcBranch::negative);
  EXPECT_EQ(ppc.branch(1), PpcBranch::negative);
  EXPECT_EQ(ppc.branch(2), PpcBranch::positive);
}

TEST(PpcInit, InitialErrorOnOrOutsideTheFunnelIsOutOfRange) {  // spec B-S10 (|e_i(0)| < ρ_i0)
  for (int axis = 0; axis < 3; ++axis)
    for (double mag : {1.0, 1.0 + 1e-12, 1.5, 10.0}) {
      Ppc ppc(scenario_params());
      V3 e0 = kE0;
      e0(axis) = std::copysign(mag * kRho.rho0, kE0(axis));
      EXPECT_EQ(ppc.init(e0), Status::out_of_range) << axis << " " << mag;
      // Branches are still set from the signs.
      EXPECT_EQ(ppc.branch(0), PpcBranch::positive);
      EXPECT_EQ(ppc.branch(2), PpcBranch::negative);
    }
  // Just inside is fine.
  Ppc ppc(scenario_params());
  EXPECT_EQ(ppc.init(V3(0.999, 0.5, -0.999) * kRho.rho0), Status::ok);
  // δ = 0 with e_i(0) = 0 sits on the edge (spec B.4-#15, Remark 1); δ > 0 admits it.
  EXPECT_EQ(ppc.init(V3(0.25 * kDeg, 0.0, -0.2 * kDeg)), Status::out_of_range);
  Ppc ppc_delta(scenario_params(0.3));
  EXPECT_EQ(ppc_delta.init(V3(0.25 * kDeg, 0.0, -0.2 * kDeg)), Status::ok);
  EXPECT_EQ(ppc_delta.branch(1), PpcBranch::positive);
  EXPECT_EQ(ppc.init(V3(kNaN, 0.0, 0.0)), Status::non_finite_input);
}

// ---------------------------------------------------------------------------------- B-S8

// e_i(t) = ρ_i(t) ζ_i(t), ζ_i = z0_i + A_i sin(w t): stays inside the funnel by construction,
// with analytic ė and ë.
struct Trajectory {
  Ppc::Params p;
  V3 z0, amp;
  double w;
  void at(double t, V3& e, V3& e_dot, V3& e_ddot) const {
    for (int i = 0; i < 3; ++i) {
      const adcs::PerformanceSample f = adcs::evaluate(p.rho[i], t);
      const double zeta = z0(i) + amp(i) * std::sin(w * t);
      const double zeta_d = amp(i) * w * std::cos(w * t);
      const double zeta_dd = -amp(i) * w * w * std::sin(w * t);
      e(i) = f.rho * zeta;
      e_dot(i) = f.rho_dot * zeta + f.rho * zeta_d;
      e_ddot(i) = f.rho_ddot * zeta + 2 * f.rho_dot * zeta_d + f.rho * zeta_dd;
    }
  }
};

void check_rates_against_finite_differences(const Trajectory& tr) {
  Ppc ppc(tr.p);
  V3 e, ed, edd;
  tr.at(0.0, e, ed, edd);
  ASSERT_EQ(ppc.init(e), Status::ok);
  const double h = 1e-4;
  for (double t : {0.3, 1.7, 4.0, 9.5, 22.0, 47.0, 80.0}) {
    Ppc::Sample sm, s0, sp;
    tr.at(t - h, e, ed, edd);
    ASSERT_EQ(ppc.transform(t - h, e, ed, sm), Status::ok);
    tr.at(t + h, e, ed, edd);
    ASSERT_EQ(ppc.transform(t + h, e, ed, sp), Status::ok);
    tr.at(t, e, ed, edd);
    ASSERT_EQ(ppc.transform(t, e, ed, s0), Status::ok);
    EXPECT_GT(s0.margin_min, 0.0);
    for (int i = 0; i < 3; ++i) {
      SCOPED_TRACE(testing::Message() << "t = " << t << ", axis " << i);
      // The sample is consistent with the pieces it is built from.
      const PpcInverse inv = inverse(e(i) / s0.rho(i), ppc.branch(i), tr.p.delta(i));
      EXPECT_NEAR(s0.z(i), e(i) / s0.rho(i), 1e-15);
      EXPECT_EQ(s0.eps(i), inv.eps);
      EXPECT_NEAR(s0.rho(i) * adcs::ppc_S(s0.eps(i), ppc.branch(i), tr.p.delta(i)), e(i),
                  1e-12 * s0.rho(i));  // e = ρ S(ε), eq. (7)
      EXPECT_GT(s0.r(i), 0.0);  // spec §B.3 step 6
      EXPECT_NEAR(s0.eps_dot(i), s0.r(i) * s0.q(i), 1e-14 * std::abs(s0.r(i) * s0.q(i)) + 1e-300);
      // ε̇ = r q against dε/dt.   spec B-S8
      const double fd_eps = (sp.eps(i) - sm.eps(i)) / (2 * h);
      EXPECT_NEAR(s0.eps_dot(i), fd_eps, 1e-6 * (std::abs(fd_eps) + 1e-3));
      // ṙ against dr/dt.   spec B-S8
      const double fd_r = (sp.r(i) - sm.r(i)) / (2 * h);
      EXPECT_NEAR(s0.r_dot(i), fd_r, 1e-6 * (std::abs(fd_r) + s0.r(i) * 1e-2));
      // q̇ = ë + q_dot_offset against dq/dt.   spec §B.3 step 9, B.4-#7
      const double fd_q = (sp.q(i) - sm.q(i)) / (2 * h);
      EXPECT_NEAR(edd(i) + s0.q_dot_offset(i), fd_q, 1e-6 * (std::abs(fd_q) + std::abs(s0.q(i)) * 1e-2));
    }
  }
}

TEST(PpcTransform, RatesMatchFiniteDifferencesAlongScenarioTrajectory) {  // spec B-S8
  // δ = 0, z0 = e(0)/ρ0 = [0.833, 0.5, −0.667]; the wobble keeps every z on its own side.
  Trajectory tr{scenario_params(), kE0 / kRho.rho0, V3(0.1, -0.3, 0.25), 0.7};
  check_rates_against_finite_differences(tr);
}

TEST(PpcTransform, RatesMatchFiniteDifferencesWithOvershootAndPerAxisFunnels) {  // spec B-S8
  // δ = 0.3: the errors cross zero (z ∈ (−0.2, 0.8) on axis 1, (−0.8, 0.2) on axis 3), and the
  // three axes have different performance functions, so channel indexing is exercised too.
  Ppc::Params p = scenario_params(0.3);
  p.rho[1] = PerformanceFunction{0.5 * kDeg, 0.01 * kDeg, 0.4};
  p.rho[2] = PerformanceFunction{0.2 * kDeg, 0.002 * kDeg, 0.05};
  p.delta(1) = 0.6;
  Trajectory tr{p, V3(0.3, 0.1, -0.3), V3(0.5, 0.55, 0.5), 1.3};
  check_rates_against_finite_differences(tr);
}

// ---------------------------------------------------------------------------------- funnel edge

TEST(PpcTransform, FunnelEdgeIsOutOfRangeWithOutputUntouched) {  // spec §B.3 step 3
  Ppc ppc(scenario_params());
  ASSERT_EQ(ppc.init(kE0), Status::ok);
  const double t = 7.0;
  const double rho = adcs::evaluate(kRho, t).rho;
  const V3 e_ok(0.5 * rho, 0.5 * rho, -0.5 * rho), ed(1e-5, -2e-5, 3e-5);
  Ppc::Sample good;
  ASSERT_EQ(ppc.transform(t, e_ok, ed, good), Status::ok);
  EXPECT_TRUE(all_fields_finite(good));
  const std::vector<V3> bad{
      V3(rho, 0.5 * rho, -0.5 * rho),          // z_1 = 1 exactly (upper edge, b = +)
      V3(2.0 * rho, 0.5 * rho, -0.5 * rho),    // z_1 beyond
      V3(0.5 * rho, 0.0, -0.5 * rho),          // z_2 = 0 = −δ (lower edge, b = +)
      V3(0.5 * rho, -1e-9, -0.5 * rho),        // e_2 on the wrong side, δ = 0
      V3(0.5 * rho, 0.5 * rho, 1e-9),          // e_3 on the wrong side, δ = 0 (b = −)
      V3(0.5 * rho, 0.5 * rho, -rho),          // z_3 = −1 (lower edge, b = −)
      V3(1e300, -1e300, 1e300)};               // absurd but finite
  for (const V3& e : bad) {
    Ppc::Sample out = sentinel_sample();
    EXPECT_EQ(ppc.transform(t, e, ed, out), Status::out_of_range) << e.transpose();
    EXPECT_TRUE(is_sentinel(out)) << e.transpose();
  }
}

TEST(PpcTransform, RobustClampFlagsTheEdgeAndStaysFinite) {  // spec §B.3 step 3 (robust mode)
  Ppc ppc(scenario_params(0.0, true));
  ASSERT_EQ(ppc.init(kE0), Status::ok);
  const double t = 7.0;
  const double rho = adcs::evaluate(kRho, t).rho;
  const V3 ed(1e-5, -2e-5, 3e-5);
  struct EdgeCase {
    V3 e;
    int axis;
    double margin;  // expected ppc_margin of the offending channel (before the clamp)
    double z_clamped;
  };
  const double m = Ppc::kClampMargin;
  const std::vector<EdgeCase> cases{
      {V3(rho, 0.5 * rho, -0.5 * rho), 0, 0.0, 1.0 - m},
      {V3(1.5 * rho, 0.5 * rho, -0.5 * rho), 0, -0.5, 1.0 - m},
      {V3(0.5 * rho, -0.2 * rho, -0.5 * rho), 1, -0.2, m},
      {V3(0.5 * rho, 0.5 * rho, 0.1 * rho), 2, -0.1, -m},
      {V3(0.5 * rho, 0.5 * rho, -3.0 * rho), 2, -2.0, -1.0 + m}};
  Ppc strict(scenario_params());
  ASSERT_EQ(strict.init(kE0), Status::ok);
  for (const EdgeCase& c : cases) {
    SCOPED_TRACE(testing::Message() << "e/rho = " << (c.e / rho).transpose());
    Ppc::Sample out = sentinel_sample();
    EXPECT_EQ(ppc.transform(t, c.e, ed, out), Status::constraint_violated);
    EXPECT_TRUE(all_fields_finite(out));
    EXPECT_NEAR(out.margin_min, c.margin, 1e-12);
    EXPECT_LE(out.margin_min, 0.0);
    EXPECT_NEAR(out.z(c.axis), c.z_clamped, 1e-15);
    EXPECT_GT(adcs::ppc_margin(out.z(c.axis), ppc.branch(c.axis), 0.0), 0.0);
    EXPECT_GT(std::abs(out.eps(c.axis)), 13.0);  // clamped 1e-12 from the edge: |ε| ≈ 13.8
    // The untouched channels equal the non-robust transform of an in-funnel error.
    V3 e_in = c.e;
    e_in(c.axis) = (c.axis == 2 ? -0.5 : 0.5) * rho;
    Ppc::Sample ref;
    ASSERT_EQ(strict.transform(t, e_in, ed, ref), Status::ok);
    for (int i = 0; i < 3; ++i) {
      if (i == c.axis) continue;
      EXPECT_EQ(out.eps(i), ref.eps(i));
      EXPECT_EQ(out.r(i), ref.r(i));
      EXPECT_EQ(out.r_dot(i), ref.r_dot(i));
      EXPECT_EQ(out.eps_dot(i), ref.eps_dot(i));
    }
  }
  // Errors far outside on every axis (10 rad ≈ 5000 ρ): still flagged and finite.
  Ppc::Sample out = sentinel_sample();
  EXPECT_EQ(ppc.transform(t, V3(10.0, -10.0, 10.0), V3(1.0, -1.0, 1.0), out),
            Status::constraint_violated);
  EXPECT_TRUE(all_fields_finite(out));
  // Inside the funnel robust mode is the plain transform (ok, positive margin).
  EXPECT_EQ(ppc.transform(t, V3(0.5 * rho, 0.5 * rho, -0.5 * rho), ed, out), Status::ok);
  EXPECT_NEAR(out.margin_min, 0.5, 1e-12);
}

TEST(PpcTransform, NonFiniteInputIsRejectedWithOutputUntouched) {
  for (bool robust : {false, true}) {
    Ppc ppc(scenario_params(0.0, robust));
    ASSERT_EQ(ppc.init(kE0), Status::ok);
    const V3 e = kE0 * 0.5, ed(1e-5, 1e-5, 1e-5);
    V3 e_nan = e, ed_inf = ed;
    e_nan(1) = kNaN;
    ed_inf(2) = kInf;
    Ppc::Sample out = sentinel_sample();
    EXPECT_EQ(ppc.transform(1.0, e_nan, ed, out), Status::non_finite_input);
    EXPECT_EQ(ppc.transform(1.0, e, ed_inf, out), Status::non_finite_input);
    EXPECT_EQ(ppc.transform(kNaN, e, ed, out), Status::non_finite_input);
    EXPECT_TRUE(is_sentinel(out));
  }
}

// ------------------------------------------------------------ funnel recovery (issue 15)

// reopen(): only the violated channel gets a new performance function, started now, with the
// error at |z| = kReopenZ, never narrower than the funnel it replaces, converging to the same
// ρ∞ at the same rate; its branch follows the sign of the error.
TEST(PpcReopen, ReopensOnlyTheViolatedChannelFromTheCurrentError) {
  Ppc ppc(scenario_params());
  ASSERT_EQ(ppc.init(kE0), Status::ok);
  const double t = 20.0, rho = adcs::evaluate(kRho, t).rho;
  const V3 e(3.0 * rho, 0.5 * rho, -0.5 * rho);  // channel 0 beyond its upper edge
  Ppc::Sample out;
  ASSERT_EQ(ppc.transform(t, e, V3::Zero(), out), Status::out_of_range);
  int n = -1;
  ASSERT_EQ(ppc.reopen(t, e, n), Status::ok);
  EXPECT_EQ(n, 1);
  EXPECT_EQ(ppc.start_time(0), t);
  EXPECT_EQ(ppc.start_time(1), 0.0);
  EXPECT_DOUBLE_EQ(ppc.active(0).rho0, e(0) / Ppc::kReopenZ);
  EXPECT_EQ(ppc.active(0).rho_inf, kRho.rho_inf);
  EXPECT_EQ(ppc.active(0).k, kRho.k);
  EXPECT_EQ(ppc.active(1).rho0, kRho.rho0);  // untouched
  EXPECT_DOUBLE_EQ(ppc.rho(0, t), e(0) / Ppc::kReopenZ);
  EXPECT_EQ(ppc.rho(1, t), rho);
  ASSERT_EQ(ppc.transform(t, e, V3::Zero(), out), Status::ok);
  EXPECT_NEAR(out.z(0), Ppc::kReopenZ, 1e-15);
  EXPECT_EQ(out.z(1), 0.5);
  // Later the re-opened funnel decays towards the same rho_inf.
  EXPECT_NEAR(ppc.rho(0, t + 200.0), kRho.rho_inf, 1e-12);
  // Nothing violated: nothing changes, n = 0.
  ASSERT_EQ(ppc.reopen(t, e, n), Status::ok);
  EXPECT_EQ(n, 0);
  EXPECT_EQ(ppc.start_time(0), t);
  // init() restores the configured funnel.
  ASSERT_EQ(ppc.init(kE0), Status::ok);
  EXPECT_EQ(ppc.start_time(0), 0.0);
  EXPECT_EQ(ppc.active(0).rho0, kRho.rho0);
}

TEST(PpcReopen, CrossingZeroWithDeltaZeroFlipsTheBranchAndNeverNarrows) {
  Ppc ppc(scenario_params());  // δ = 0: an error may not cross zero
  ASSERT_EQ(ppc.init(kE0), Status::ok);
  const double t = 1.0, rho = adcs::evaluate(kRho, t).rho;
  const V3 e(-1e-3 * rho, 0.5 * rho, -0.5 * rho);  // channel 0 just below zero on branch +
  int n = 0;
  ASSERT_EQ(ppc.reopen(t, e, n), Status::ok);
  EXPECT_EQ(n, 1);
  EXPECT_EQ(ppc.branch(0), PpcBranch::negative);
  EXPECT_EQ(ppc.active(0).rho0, rho);  // |e|/0.5 is tiny: the funnel in force is kept
  Ppc::Sample out;
  EXPECT_EQ(ppc.transform(t, e, V3::Zero(), out), Status::ok);
  // Late in the run rho(t) = rho_inf to machine precision: the new rho0 is 2 rho_inf (> rho_inf).
  const double late = 1e4;
  ASSERT_EQ(ppc.init(kE0), Status::ok);
  ASSERT_EQ(ppc.rho(1, late), kRho.rho_inf);
  ASSERT_EQ(ppc.reopen(late, V3(0.5 * kRho.rho_inf, -1e-12, -0.5 * kRho.rho_inf), n), Status::ok);
  EXPECT_EQ(ppc.active(1).rho0, 2.0 * kRho.rho_inf);
  EXPECT_TRUE(adcs::valid(ppc.active(1)));
}

TEST(PpcReopen, RefusesWhatNoFunnelCanHoldAndChangesNothing) {
  Ppc ppc(scenario_params());
  ASSERT_EQ(ppc.init(kE0), Status::ok);
  const double t = 5.0, rho = adcs::evaluate(kRho, t).rho;
  int n = 7;
  // δ = 0 and e_1 = 0 exactly: on the edge of both branches.
  EXPECT_EQ(ppc.reopen(t, V3(0.0, 0.5 * rho, -0.5 * rho), n), Status::out_of_range);
  EXPECT_EQ(n, 0);
  // ρ0' = |e|/0.5 overflows.
  EXPECT_EQ(ppc.reopen(t, V3(1.5e308, 0.5 * rho, -0.5 * rho), n), Status::out_of_range);
  EXPECT_EQ(ppc.reopen(t, V3(kNaN, 0.5 * rho, -0.5 * rho), n), Status::non_finite_input);
  EXPECT_EQ(ppc.reopen(kInf, V3(2.0 * rho, 0.5 * rho, -0.5 * rho), n), Status::non_finite_input);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(ppc.start_time(i), 0.0) << i;
    EXPECT_EQ(ppc.active(i).rho0, kRho.rho0) << i;
  }
  EXPECT_EQ(ppc.branch(0), PpcBranch::positive);
  EXPECT_EQ(ppc.branch(2), PpcBranch::negative);
  // An unknown recovery value is refused at construction.
  Ppc::Params bad = scenario_params();
  bad.recovery = static_cast<adcs::FunnelRecovery>(7);
  EXPECT_EQ(Ppc(bad).status(), Status::invalid_parameter);
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
