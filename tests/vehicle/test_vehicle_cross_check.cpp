// The file path builds the same loop as the registered scenario: the cubesat example with its
// sensors and disturbances removed (perfect measurements, no external torque; [knowledge] is absent,
// so the controller believes the truth) is cubesat-mrp-pd — same plant, law, allocation and
// limits. Given the registered scenario's own values to the last bit (its pyramid has
// cos 90° = 6e-17 where the file writes 0, its gain 2 x 0.2 x 0.1 = 0.04000000000000001 where the
// file writes 0.04), the two runs are bit-identical; with the file's decimals they agree to
// round-off (CVODE at rtol 1e-12 turns the ulps into ~1e-12 relative).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "adcs/core/types.hpp"
#include "vehicle_test_util.hpp"

namespace ADCS_UNITY_ID {
using adcs::sim::RunContext;
using adcs::sim::RunResult;
using namespace adcs::sim::test;

using Columns = std::map<std::string, std::vector<double>>;

//! Columns of a CSV written by CsvRecorder (line 1: units, line 2: names).
Columns read_csv(const std::string& path) {
  std::ifstream in(path);
  std::string units, header, line;
  std::getline(in, units);
  std::getline(in, header);
  std::vector<std::string> names;
  std::istringstream h(header);
  for (std::string n; std::getline(h, n, ',');) names.push_back(n);
  Columns cols;
  while (std::getline(in, line)) {
    std::istringstream l(line);
    std::size_t i = 0;
    for (std::string v; std::getline(l, v, ','); ++i) cols[names.at(i)].push_back(std::stod(v));
  }
  return cols;
}

struct Runs {
  RunResult file, registered;
  Columns file_csv, registered_csv;
};

//! The cubesat file without sensors and disturbances, with the registered scenario's integrator
//! tolerances and settling band (1e-3 rad) and `sets`, and cubesat-mrp-pd, both with CSVs.
Runs run_both(const std::vector<std::pair<std::string, std::string>>& sets) {
  const auto dir = fresh_test_dir("vehicle_cross_check");
  const std::string text = drop_tables(read_text(example_path("cubesat-12u.toml")), {"[sensors", "[disturbances"});
  EXPECT_EQ(text.find("[sensors"), std::string::npos);
  const std::string path = write_file(dir, "cubesat-perfect.toml", text);
  std::vector<std::pair<std::string, std::string>> s{
      {"rtol", "1e-12"}, {"atol", "1e-14"}, {"requirements.pointing_deg", adcs::sim::format_number(1e-3 * 180.0 / adcs::kPiRad)}};
  s.insert(s.end(), sets.begin(), sets.end());
  Runs r;
  r.file = run_file(path, s, 0, (dir / "file.csv").string());
  const adcs::sim::Scenario* reg = adcs::sim::find_scenario("cubesat-mrp-pd");
  EXPECT_NE(reg, nullptr);
  adcs::sim::ParamSet ps;
  reg->declare(ps);
  RunContext ctx;
  ctx.quiet = true;
  ctx.csv_path = (dir / "registered.csv").string();
  r.registered = reg->run(ps, ctx);
  r.file_csv = read_csv((dir / "file.csv").string());
  r.registered_csv = read_csv(ctx.csv_path);
  return r;
}

//! The file's metric against the registered one's (its torque_max_Nm is the max wheel motor torque).
void expect_metrics(const Runs& r, double tol) {
  const std::pair<const char*, const char*> same[] = {
      {"settle_s", "settle_s"},
      {"att_err_max_deg", "att_err_max_deg"},
      {"att_err_final_deg", "att_err_final_deg"},
      {"wheel_speed_max_rad_s", "wheel_speed_max_rad_s"},
      {"wheel_torque_max_Nm", "torque_max_Nm"},
      {"saturated_fraction", "saturated_fraction"},
      {"rejected_steps", "rejected_steps"},
      {"wheel_speed_held", "wheel_speed_held"}};
  for (const auto& [f, g] : same) {
    const double a = metric(r.file, f), b = metric(r.registered, g);
    if (tol == 0.0) {
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << f << ": " << a << " vs " << b;
    } else {
      EXPECT_NEAR(a, b, tol * std::max(1.0, std::abs(b))) << f;
    }
  }
  EXPECT_EQ(metric(r.file, "settle_s"), 77.4);  // docs/USER-GUIDE.md's number
  EXPECT_EQ(metric(r.file, "star_tracker_samples"), 0.0);
}

//! The time series, sample by sample: |a - b| <= tol * max |b| per column.
void expect_series(Runs& r, double tol) {
  auto& a = r.file_csv;
  auto& b = r.registered_csv;
  ASSERT_EQ(a["t"].size(), b["t"].size());
  ASSERT_GT(a["t"].size(), 4000u);
  std::vector<std::string> cols{"t"};
  for (int i = 1; i <= 3; ++i)
    for (const char* c : {"sigma_BN_", "omega_BN_B_", "L_r_B_"}) cols.push_back(c + std::to_string(i));
  for (int j = 1; j <= 4; ++j)
    for (const char* c : {"u_s_", "Omega_"}) cols.push_back(c + std::to_string(j));
  for (const std::string& c : cols) {
    double worst = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < a[c].size(); ++i) {
      worst = std::max(worst, std::abs(a[c][i] - b[c][i]));
      scale = std::max(scale, std::abs(b[c][i]));
    }
    EXPECT_LE(worst, tol * scale) << c << " (max |value| " << scale << ")";
  }
}

TEST(VehicleCrossCheck, CubesatFileWithTheRegisteredValuesIsCubesatMrpPdBitForBit) {
  adcs::sim::ParamSet reg;
  adcs::sim::find_scenario("cubesat-mrp-pd")->declare(reg);
  const std::string axes = adcs::sim::format_value(reg.at("wheel_axes_B"));
  Runs r = run_both({{"wheels.axes_B", axes},
                     {"knowledge.wheel_axes_B", axes},
                     {"controller.P_Nms", adcs::sim::format_value(reg.at("P_Nms"))},
                     {"controller.K_Nm", adcs::sim::format_value(reg.at("K_Nm"))},
                     {"reference.sigma_RN", adcs::sim::format_value(reg.at("sigma_RN"))}});
  expect_metrics(r, 0.0);
  expect_series(r, 0.0);
}

TEST(VehicleCrossCheck, CubesatFileAsWrittenIsCubesatMrpPdToRoundOff) {
  Runs r = run_both({});
  expect_metrics(r, 1e-9);
  expect_series(r, 1e-11);
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
