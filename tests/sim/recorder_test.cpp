// CsvRecorder: header lines, decimation, final row, exact round trip of %.17g.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "sim/recorder.hpp"

namespace ADCS_UNITY_ID {

using adcs::sim::Column;
using adcs::sim::CsvRecorder;
using adcs::sim::SimError;

std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> values;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');) values.push_back(std::strtod(cell.c_str(), nullptr));
  return values;
}

std::uint64_t bits(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Why the pid: several build trees may run this test at the same time.
std::string temp_path(const char* name) {
  return ::testing::TempDir() + std::to_string(::getpid()) + "_" + name;
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

TEST(CsvRecorder, HeaderDecimationFinalRowAndExactRoundTrip) {
  const std::string path = temp_path("adcs_sim_recorder_test.csv");
  {
    CsvRecorder rec(path, {{"t", "s"}, {"sigma_BN_1", "-"}, {"omega_BN_B_1", "rad/s"}}, 3);
    for (int k = 0; k < 7; ++k) rec.record({0.1 * k, 1.0 / 3.0 + k, -std::exp(-k)});  // calls 0..6
    const Eigen::Vector3d last(0.7, 5e-324, -0.0);
    rec.record_final(last);  // call 7: not a multiple of 3, written anyway
    EXPECT_EQ(rec.rows_written(), 4u);  // calls 0, 3, 6 and the final one
  }
  const std::vector<std::string> lines = read_lines(path);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "# units: t [s], sigma_BN_1 [-], omega_BN_B_1 [rad/s]");
  EXPECT_EQ(lines[1], "t,sigma_BN_1,omega_BN_B_1");
  const int kept[] = {0, 3, 6};
  for (int r = 0; r < 3; ++r) {
    const int k = kept[r];
    const std::vector<double> row = parse_row(lines[2 + r]);
    ASSERT_EQ(row.size(), 3u);
    EXPECT_EQ(bits(row[0]), bits(0.1 * k));
    EXPECT_EQ(bits(row[1]), bits(1.0 / 3.0 + k));
    EXPECT_EQ(bits(row[2]), bits(-std::exp(-k)));
  }
  const std::vector<double> final_row = parse_row(lines[5]);
  EXPECT_EQ(bits(final_row[0]), bits(0.7));
  EXPECT_EQ(bits(final_row[1]), bits(5e-324));  // smallest subnormal survives
  EXPECT_EQ(bits(final_row[2]), bits(-0.0));    // and the sign of zero
  std::remove(path.c_str());
}

TEST(CsvRecorder, RawPointerOverloadAndClose) {
  const std::string path = temp_path("adcs_sim_recorder_raw.csv");
  CsvRecorder rec(path, {{"t", "s"}, {"x", "m"}});
  const double values[] = {1.0, 2.5};
  rec.record(values);
  rec.close();
  rec.close();  // idempotent
  EXPECT_THROW(rec.record(values), SimError);
  const std::vector<std::string> lines = read_lines(path);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[2], "1,2.5");
  std::remove(path.c_str());
}

TEST(CsvRecorder, ErrorsThrow) {
  EXPECT_THROW(CsvRecorder("/nonexistent-dir/adcs/x.csv", {{"t", "s"}}), SimError);
  const std::string path = temp_path("adcs_sim_recorder_errors.csv");
  EXPECT_THROW(CsvRecorder(path, {}), SimError);
  EXPECT_THROW(CsvRecorder(path, {{"a,b", "s"}}), SimError);
  EXPECT_THROW(CsvRecorder(path, {{"t", "s"}}, 0), SimError);
  CsvRecorder rec(path, {{"t", "s"}, {"x", "m"}});
  EXPECT_THROW(rec.record({1.0}), SimError);
  EXPECT_THROW(rec.record(Eigen::VectorXd::Zero(3)), SimError);
  rec.close();
  std::remove(path.c_str());
}
