// Vehicle-file runs: reproducibility (same seed: bit-identical metrics; another seed: other sensor
// noise), every supported actuator set flies, the PPC law through a file is cubesat-ppc-10hz, a
// dispersed truth leaves the controller's knowledge nominal, the CSV has its columns.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>

#include "adcs/core/types.hpp"
#include "vehicle_test_util.hpp"

namespace ADCS_UNITY_ID {
using adcs::sim::RunResult;
using namespace adcs::sim::test;

TEST(VehicleRuns, SameSeedBitIdenticalOtherSeedOtherNoise) {
  const std::string path = example_path("cubesat-12u.toml");
  const std::vector<std::pair<std::string, std::string>> short_run{{"duration_s", "100"}, {"steady_window_s", "[50, 100]"}};
  const RunResult a = run_file(path, short_run, 7), b = run_file(path, short_run, 7), c = run_file(path, short_run, 8);
  ASSERT_EQ(a.metrics.size(), b.metrics.size());
  for (std::size_t i = 0; i < a.metrics.size(); ++i)
    EXPECT_EQ(std::memcmp(&a.metrics[i].second, &b.metrics[i].second, sizeof(double)), 0) << a.metrics[i].first;
  EXPECT_NE(metric(a, "att_knowledge_err_max_deg"), metric(c, "att_knowledge_err_max_deg"));
  EXPECT_NE(metric(a, "att_err_ss_max_deg"), metric(c, "att_err_ss_max_deg"));
}

//! A vehicle with M CMGs (pyramid, 54.74 deg skew) and/or N wheels (pyramid at 30 deg, or 3
//! orthogonal with CMGs), MRP PD, a 20 deg slew about (1, 1, 1)/sqrt(3), perfect sensors.
std::string vehicle_text(int m, int n) {
  std::ostringstream s;
  s.precision(17);
  const double kPi = adcs::kPiRad;
  s << "name = \"set-" << m << "-" << n << "\"\ndescription = \"actuator set test\"\n"
    << "[run]\nduration_s = 120.0\ncontrol_period_s = 0.1\nsteady_window_s = [100.0, 120.0]\n"
    << "[spacecraft]\nJ_kgm2 = [[10.0, 0.0, 0.0], [0.0, 12.0, 0.0], [0.0, 0.0, 8.0]]\n";
  auto vec = [&](int k, double x) {
    s << "[";
    for (int i = 0; i < k; ++i) s << (i ? ", " : "") << x;
    s << "]\n";
  };
  if (n > 0) {
    s << "[wheels]\naxes_B = [";
    for (int j = 0; j < n; ++j) {
      double a = 2.0 * kPi * j / n, e = kPi / 6.0;
      double v[3] = {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
      if (m > 0)  // with CMGs: 3 orthogonal wheels
        for (int i = 0; i < 3; ++i) v[i] = i == j ? 1.0 : 0.0;
      s << (j ? ", " : "") << "[" << v[0] << ", " << v[1] << ", " << v[2] << "]";
    }
    s << "]\nJ_s_kgm2 = ";
    vec(n, 0.01);
    s << "torque_max_Nm = ";
    vec(n, 0.2);
    s << "speed_max_rad_s = ";
    vec(n, 600.0);
  }
  if (m > 0) {
    const double b = std::acos(1.0 / std::sqrt(3.0));
    s << "[cmgs]\ngimbal_axes_B = [";
    for (int i = 0; i < m; ++i) {
      const double a = 2.0 * kPi * i / m;
      s << (i ? ", " : "") << "[" << std::sin(b) * std::cos(a) << ", " << std::sin(b) * std::sin(a) << ", " << std::cos(b) << "]";
    }
    s << "]\nspin_axes_B = [";
    for (int i = 0; i < m; ++i) {
      const double a = 2.0 * kPi * i / m;
      s << (i ? ", " : "") << "[" << -std::sin(a) << ", " << std::cos(a) << ", 0.0]";
    }
    s << "]\nh_Nms = ";
    vec(m, 2.0);
    s << "gimbal_rate_max_rad_s = ";
    vec(m, 1.0);
  }
  // Critically damped at 0.2 rad/s: K = 4 J_max w^2, P_i = 2 sqrt(J_i K / 4).
  s << "[controller]\ntype = \"mrp_pd\"\nK_Nm = 1.92\nP_Nms = [" << 2.0 * std::sqrt(10.0 * 0.48) << ", "
    << 2.0 * std::sqrt(12.0 * 0.48) << ", " << 2.0 * std::sqrt(8.0 * 0.48) << "]\n"
    << "[actuation]\ntype = \"" << (m > 0 ? "vscmg_steering" : "rw_allocation") << "\"\n"
    << "[reference]\nsigma_RN = [" << std::tan(20.0 * kPi / 720.0) / std::sqrt(3.0) << ", "
    << std::tan(20.0 * kPi / 720.0) / std::sqrt(3.0) << ", " << std::tan(20.0 * kPi / 720.0) / std::sqrt(3.0) << "]\n"
    << "[requirements]\npointing_deg = 0.01\n";
  return s.str();
}

TEST(VehicleRuns, EverySupportedActuatorSetFlies) {
  const auto dir = fresh_test_dir("vehicle_sets");
  const std::pair<int, int> sets[] = {{0, 3}, {0, 4}, {0, 5}, {0, 6}, {3, 0}, {4, 0}, {5, 0}, {6, 0}, {4, 3}};
  for (const auto& [m, n] : sets) {
    const std::string name = std::to_string(m) + "x" + std::to_string(n);
    const std::string path = write_file(dir, name + ".toml", vehicle_text(m, n));
    const RunResult r = run_file(path, {}, 0, (dir / (name + ".csv")).string());
    EXPECT_EQ(metric(r, "rejected_steps"), 0.0) << name;
    EXPECT_LT(metric(r, "att_err_ss_max_deg"), 0.01) << name;  // the 20 deg slew settled
    EXPECT_NEAR(metric(r, "att_err_max_deg"), 20.0, 1e-6) << name;
    ASSERT_EQ(r.claims.size(), 1u) << name;
    EXPECT_TRUE(r.claims[0].holds.value_or(false)) << name << ": " << r.claims[0].ours;
    if (m > 0) {
      EXPECT_LE(metric(r, "gimbal_rate_peak_rad_s"), 1.0) << name;
    } else {
      EXPECT_LE(metric(r, "wheel_torque_max_Nm"), 0.2) << name;
    }
    // The CSV has the common columns and one per actuator.
    const std::string header = read_text((dir / (name + ".csv")).string());
    for (const char* col : {"t,att_err_deg,sigma_BN_1", "omega_BN_B_3", "torque_B_1", "L_r_B_1", "star_tracker_valid"})
      EXPECT_NE(header.find(col), std::string::npos) << name << " " << col;
    if (m > 0) {
      EXPECT_NE(header.find("gamma_" + std::to_string(m) + ","), std::string::npos) << name;
    } else {
      EXPECT_NE(header.find("u_s_" + std::to_string(n) + ","), std::string::npos) << name;
    }
    if (n > 0) {
      EXPECT_NE(header.find("Omega_" + std::to_string(n)), std::string::npos) << name;
    }
  }
}

// The PPC law through a file on the cubesat with perfect sensors and no disturbance is the
// registered cubesat-ppc-10hz (same plant, law and set, allocation, limits).
TEST(VehicleRuns, PpcFileIsCubesatPpc10hz) {
  const auto dir = fresh_test_dir("vehicle_ppc");
  std::string text = drop_tables(read_text(example_path("cubesat-12u.toml")),
                                 {"[sensors", "[disturbances", "[controller", "[requirements"});
  text += R"([controller]
type = "ppc"
rho0_deg = [40.0, 40.0, 40.0]
rho_inf_deg = [0.05, 0.05, 0.05]
k_rho = [0.08, 0.08, 0.08]
delta = [1.0, 1.0, 1.0]
lambda = [0.1, 0.1, 0.1]
K = [3.5e-4, 3.5e-4, 3.5e-4]
tau_w = [1e-3, 1e-3, 1e-3]
tau_mu = 1e-3
beta = 0.01
gamma = 10.0
sigma = 1.0
[requirements]
pointing_deg = 0.05729577951308232
)";
  const RunResult file = run_file(write_file(dir, "ppc.toml", text), {{"rtol", "1e-12"}, {"atol", "1e-14"}});
  const adcs::sim::Scenario* reg = adcs::sim::find_scenario("cubesat-ppc-10hz");
  ASSERT_NE(reg, nullptr);
  adcs::sim::ParamSet ps;
  reg->declare(ps);
  adcs::sim::RunContext ctx;
  const RunResult registered = reg->run(ps, ctx);
  EXPECT_NEAR(metric(file, "att_err_max_deg"), metric(registered, "att_err_max_deg"), 1e-9);
  EXPECT_NEAR(metric(file, "att_err_final_deg"), metric(registered, "att_err_final_deg"), 1e-9);
  EXPECT_EQ(metric(file, "settle_s"), metric(registered, "settle_s"));
  EXPECT_EQ(metric(file, "funnel_recoveries"), metric(registered, "funnel_recoveries"));
  EXPECT_NEAR(metric(file, "wheel_torque_max_Nm"), metric(registered, "torque_max_Nm"), 1e-12);
  EXPECT_EQ(metric(file, "rejected_steps"), metric(registered, "rejected_steps"));
}

// A Monte Carlo disperses the truth: the controller keeps the nominal knowledge, so the run
// differs from one where the controller is told the dispersed inertia too.
TEST(VehicleRuns, DispersedTruthLeavesTheKnowledgeNominal) {
  const std::string path = example_path("cubesat-12u.toml");
  const std::string J = "[[0.24,0.01,0],[0.01,0.22,0],[0,0,0.17]]";
  const std::vector<std::pair<std::string, std::string>> base{{"duration_s", "150"}, {"steady_window_s", "[100, 150]"}};
  auto with = [&](std::vector<std::pair<std::string, std::string>> extra) {
    auto s = base;
    s.insert(s.end(), extra.begin(), extra.end());
    return run_file(path, s, 1);
  };
  const RunResult nominal = with({});
  const RunResult truth_only = with({{"spacecraft.J_kgm2", J}});
  const RunResult both = with({{"spacecraft.J_kgm2", J}, {"knowledge.J_kgm2", J}});
  EXPECT_NE(metric(truth_only, "wheel_speed_max_rad_s"), metric(nominal, "wheel_speed_max_rad_s"));
  EXPECT_NE(metric(truth_only, "wheel_speed_max_rad_s"), metric(both, "wheel_speed_max_rad_s"));
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
