// Dispersions (src/campaign/dispersion.hpp) and counter-based seeding (seeding.hpp): the forms,
// their refusals, the physics-keeping inertia and axis draws, and that a draw depends only on
// (seed0, run, key).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "adcs/core/types.hpp"
#include "campaign/dispersion.hpp"
#include "campaign/seeding.hpp"
#include "campaign/statistics.hpp"

namespace adcs::sim::campaign {
namespace ADCS_UNITY_ID {

ParamSet vehicle_params() {
  ParamSet p;
  p.number("duration_s", 10.0, "s", "test");
  p.number("control_period_s", 0.1, "s", "test");
  p.number("gain", 2.0, "-", "test");
  p.vector("bias", {1.0, -2.0, 3.0}, "rad/s", "test");
  p.matrix("spacecraft.J_kgm2", {{0.20, 0.0, 0.0}, {0.0, 0.25, 0.0}, {0.0, 0.0, 0.15}}, "kg m^2", "test");
  const double s = std::sqrt(0.5);
  p.matrix("wheels.axes_B", {{s, 0.0, s}, {0.0, s, s}, {-s, 0.0, s}, {0.0, -s, s}}, "-", "test");
  p.name("law", "pd", {"pd"}, "test");
  return p;
}

Mat3 mat(const ParamValue& v) {
  Mat3 J;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) J(i, j) = v.matrix[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  return J;
}

TEST(Dispersion, ParsesEveryForm) {
  EXPECT_EQ(parse_dispersion("gain=normal(1, 0.1)").form, Dispersion::Form::normal);
  EXPECT_EQ(parse_dispersion("gain=uniform(0,1)").form, Dispersion::Form::uniform);
  EXPECT_EQ(parse_dispersion("gain=truncnormal(1,0.1,0.9,1.1)").form, Dispersion::Form::truncnormal);
  EXPECT_EQ(parse_dispersion("gain=rel_normal(0.05)").form, Dispersion::Form::rel_normal);
  EXPECT_EQ(parse_dispersion("gain=rel_uniform(0.1)").form, Dispersion::Form::rel_uniform);
  const Dispersion d = parse_dispersion(" spacecraft.J_kgm2 = inertia(0.1, 1) ");
  EXPECT_EQ(d.key, "spacecraft.J_kgm2");
  EXPECT_EQ(d.form, Dispersion::Form::inertia);
  ASSERT_EQ(d.args.size(), 2u);
  EXPECT_EQ(parse_dispersion("wheels.axes_B=axes(0.5)").form, Dispersion::Form::axes);
}

TEST(Dispersion, RefusesMalformedExpressionsWithOneLineReasons) {
  for (const char* bad : {"gain", "=normal(0,1)", "gain=normal(0)", "gain=normal(0,1,2)", "gain=gauss(0,1)",
                          "gain=normal(0,-1)", "gain=uniform(2,1)", "gain=normal(0,x)", "gain=normal(0,nan)",
                          "gain=normal(0,1) extra", "gain=truncnormal(0,1,5,6)", "gain=truncnormal(0,1,1,1)",
                          "gain=rel_uniform(-0.1)", "gain=normal 0,1"}) {
    try {
      parse_dispersion(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const ParamError& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << bad;
    }
  }
}

TEST(Dispersion, ChecksTheKeyAndTheShape) {
  const ParamSet p = vehicle_params();
  EXPECT_NO_THROW(check_dispersion(parse_dispersion("spacecraft.J_kgm2=inertia(0.1,1)"), p));
  EXPECT_NO_THROW(check_dispersion(parse_dispersion("wheels.axes_B=axes(0.5)"), p));
  EXPECT_THROW(check_dispersion(parse_dispersion("spacecraft.J=rel_normal(0.1)"), p), ParamError);
  EXPECT_THROW(check_dispersion(parse_dispersion("law=normal(0,1)"), p), ParamError);
  EXPECT_THROW(check_dispersion(parse_dispersion("bias=inertia(0.1,1)"), p), ParamError);
  try {
    check_dispersion(parse_dispersion("spacecraft.J_kgm=rel_normal(0.1)"), p);
    FAIL();
  } catch (const ParamError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean spacecraft.J_kgm2"), std::string::npos) << e.what();
  }
}

TEST(Dispersion, ADrawDependsOnlyOnSeedRunAndKey) {
  const ParamSet p = vehicle_params();
  const Dispersion d = parse_dispersion("bias=normal(0, 1)");
  const DrawnValue a = draw(d, p, 7, 3), b = draw(d, p, 7, 3);
  EXPECT_EQ(a.value.vector, b.value.vector);
  EXPECT_NE(draw(d, p, 7, 4).value.vector, a.value.vector);
  EXPECT_NE(draw(d, p, 8, 3).value.vector, a.value.vector);
  // Another key's stream is unrelated: drawing it does not change this one (order independent).
  const Dispersion g = parse_dispersion("gain=normal(0, 1)");
  (void)draw(g, p, 7, 3);
  EXPECT_EQ(draw(d, p, 7, 3).value.vector, a.value.vector);
  EXPECT_NE(stream_seed(7, 3, "bias"), stream_seed(7, 3, "gain"));
  EXPECT_NE(run_seed(1, 1), run_seed(2, 0));  // unlike seed0 + k
  EXPECT_NE(run_seed(0, 0), 0u);
}

TEST(Dispersion, ElementWiseFormsHaveTheirMoments) {
  const ParamSet p = vehicle_params();
  std::vector<double> rel, uni, trunc;
  for (std::uint64_t k = 0; k < 20000; ++k) {
    rel.push_back(draw(parse_dispersion("gain=rel_normal(0.1)"), p, 1, k).value.number);
    uni.push_back(draw(parse_dispersion("gain=uniform(-1, 3)"), p, 1, k).value.number);
    trunc.push_back(draw(parse_dispersion("gain=truncnormal(0, 1, -0.5, 2)"), p, 1, k).value.number);
  }
  const Summary r = summarize(rel), u = summarize(uni), t = summarize(trunc);
  EXPECT_NEAR(r.mean, 2.0, 0.01);  // nominal 2 x (1 + N(0, 0.1²))
  EXPECT_NEAR(r.std, 0.2, 0.01);
  EXPECT_GE(u.min, -1.0);
  EXPECT_LE(u.max, 3.0);
  EXPECT_NEAR(u.mean, 1.0, 0.05);
  EXPECT_GE(t.min, -0.5);
  EXPECT_LE(t.max, 2.0);
}

TEST(Dispersion, InertiaKeepsPhysics) {
  const ParamSet p = vehicle_params();
  const Dispersion d = parse_dispersion("spacecraft.J_kgm2=inertia(0.05, 2)");
  const Param& J = p.at("spacecraft.J_kgm2");
  double max_rel = 0.0;
  for (std::uint64_t k = 0; k < 200; ++k) {
    const DrawnValue v = draw(d, p, 3, k);
    const Mat3 M = mat(v.value);
    EXPECT_EQ(M, M.transpose());  // symmetric to the last bit
    const Vec3 l = Eigen::SelfAdjointEigenSolver<Mat3>(M).eigenvalues();
    EXPECT_GT(l(0), 0.0);
    EXPECT_FALSE(physical_problem(d, v, J).has_value());
    max_rel = std::max(max_rel, std::abs(M(1, 1) / 0.25 - 1.0));
  }
  EXPECT_GT(max_rel, 0.02);  // it does disperse
  // A relative element-wise draw that breaks the triangle inequality is reported, never fixed.
  DrawnValue bad{"spacecraft.J_kgm2", ParamKind::matrix, J.value};
  bad.value.matrix[2][2] = 0.5;  // 0.20 + 0.25 < 0.5
  const auto problem = physical_problem(parse_dispersion("spacecraft.J_kgm2=rel_normal(0.1)"), bad, J);
  ASSERT_TRUE(problem.has_value());
  EXPECT_NE(problem->find("triangle"), std::string::npos);
  bad.value.matrix[2][2] = -0.1;
  EXPECT_NE(physical_problem(parse_dispersion("spacecraft.J_kgm2=rel_normal(0.1)"), bad, J)->find("positive definite"),
            std::string::npos);
}

TEST(Dispersion, AxesTiltByTheGivenAngleAndStayUnit) {
  const ParamSet p = vehicle_params();
  const Dispersion d = parse_dispersion("wheels.axes_B=axes(0.5)");
  std::vector<double> tilt_deg;
  for (std::uint64_t k = 0; k < 4000; ++k) {
    const DrawnValue v = draw(d, p, 5, k);
    for (std::size_t i = 0; i < 4; ++i) {
      const Vec3 a(v.value.matrix[i][0], v.value.matrix[i][1], v.value.matrix[i][2]);
      const auto& n0 = p.at("wheels.axes_B").value.matrix[i];
      EXPECT_NEAR(a.norm(), 1.0, 1e-14);
      tilt_deg.push_back(std::acos(std::min(1.0, a.dot(Vec3(n0[0], n0[1], n0[2])))) * 180.0 / 3.14159265358979323846);
    }
  }
  // Rayleigh(σ = 0.5 deg): mean σ sqrt(π/2) = 0.627 deg.
  EXPECT_NEAR(summarize(tilt_deg).mean, 0.5 * std::sqrt(3.14159265358979323846 / 2.0), 0.02);
}

TEST(Dispersion, ElementNamesAreRowMajor) {
  const ParamSet p = vehicle_params();
  const DrawnValue v = draw(parse_dispersion("spacecraft.J_kgm2=rel_normal(0)"), p, 1, 0);
  const auto n = element_names(v);
  ASSERT_EQ(n.size(), 9u);
  EXPECT_EQ(n[1], "spacecraft.J_kgm2[0][1]");
  EXPECT_EQ(element_values(v)[4], 0.25);  // sd 0: the nominal, exactly
  EXPECT_EQ(element_names(draw(parse_dispersion("bias=normal(0,1)"), p, 1, 0))[2], "bias[2]");
}

TEST(Statistics, PercentilesInterpolateLikeNumpy) {
  EXPECT_DOUBLE_EQ(percentile_sorted({1, 2, 3, 4}, 50.0), 2.5);
  EXPECT_DOUBLE_EQ(percentile_sorted({1, 2, 3, 4, 5}, 95.0), 4.8);
  const Summary s = summarize({3.0, NAN, 1.0, 2.0, INFINITY});
  EXPECT_EQ(s.count, 3u);
  EXPECT_EQ(s.nonfinite, 2u);
  EXPECT_DOUBLE_EQ(s.median, 2.0);
  EXPECT_DOUBLE_EQ(s.std, 1.0);
  EXPECT_TRUE(std::isnan(summarize({}).median));
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
}  // namespace adcs::sim::campaign
