// Loading vehicle files: the examples' parameters (dotted names, FILE:LINE sources, knowledge
// defaults), and every error path giving one line "FILE:LINE: ..." (issue 18).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>

#include "vehicle/schema.hpp"
#include "vehicle_test_util.hpp"

namespace ADCS_UNITY_ID {
using adcs::sim::ParamError;
using adcs::sim::ParamSet;
using namespace adcs::sim::test;

// A small valid file: 3 orthogonal wheels, MRP PD. Single-line values, so tests replace lines.
const char* kMinimal = R"(name = "minimal"
description = "three orthogonal wheels"
[run]
duration_s = 2.0
control_period_s = 0.1
steady_window_s = [1.0, 2.0]
[spacecraft]
J_kgm2 = [[1.0, 0.0, 0.0], [0.0, 1.2, 0.0], [0.0, 0.0, 0.8]]
[wheels]
axes_B = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
J_s_kgm2 = [1e-3, 1e-3, 1e-3]
torque_max_Nm = [0.01, 0.01, 0.01]
speed_max_rad_s = [600.0, 600.0, 600.0]
[controller]
type = "mrp_pd"
K_Nm = 0.1
P_Nms = [0.5, 0.5, 0.5]
[actuation]
type = "rw_allocation"
[reference]
sigma_RN = [0.0, 0.0, 0.1]
)";

class VehicleLoader : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = fresh_test_dir("vehicle_loader"); }

  //! Loading `text` fails with one line "PATH:LINE: ..." containing `what` (line 0: "PATH: ...").
  void expect_error(const std::string& text, int line, const std::string& what) {
    const std::string path = write_file(dir_, "v.toml", text);
    const std::string where = line > 0 ? path + ":" + std::to_string(line) + ": " : path + ": ";
    try {
      adcs::sim::vehicle::load_vehicle_file(path);
      ADD_FAILURE() << "no error; expected " << where << "..." << what;
    } catch (const ParamError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind(where, 0), 0u) << m;
      EXPECT_NE(m.find(what), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
  std::string replaced(const std::string& prefix, const std::string& by) const { return replace_line(kMinimal, prefix, by); }
  int line(const std::string& prefix) const { return line_of(kMinimal, prefix); }
  //! The line number of text appended to kMinimal (its first appended line).
  static int next() { return static_cast<int>(std::count(kMinimal, kMinimal + std::strlen(kMinimal), '\n')) + 1; }

  std::filesystem::path dir_;
};

TEST_F(VehicleLoader, MinimalFileLoadsAndRuns) {
  const std::string path = write_file(dir_, "v.toml", kMinimal);
  const adcs::sim::RunResult r = run_file(path);
  EXPECT_EQ(r.metric("rejected_steps"), 0.0);
  EXPECT_TRUE(std::isnan(r.metric("settle_s")));  // no pointing requirement: no band
  EXPECT_TRUE(r.claims.empty());
}

TEST_F(VehicleLoader, ExamplesDeclareTheirValuesByDottedPathWithFileAndLine) {
  for (const char* file : {"cubesat-12u.toml", "cmg-imager.toml"}) {
    const std::string path = example_path(file);
    const std::string text = read_text(path);
    const LoadedVehicle v = load(path);
    EXPECT_EQ(v.scenario->name(), std::string(file).substr(0, std::string(file).size() - 5));
    EXPECT_FALSE(v.scenario->description().empty());
    const ParamSet& p = v.params;
    // The scenario contract's run parameters keep their plain names.
    EXPECT_EQ(p.at("duration_s").source, path + ":" + std::to_string(line_of(text, "duration_s")));
    EXPECT_EQ(p.at("control_period_s").kind, adcs::sim::ParamKind::number);
    // Truth: spacecraft.J_kgm2, exactly this name, sourced at its line.
    EXPECT_EQ(p.at("spacecraft.J_kgm2").source, path + ":" + std::to_string(line_of(text, "J_kgm2")));
    EXPECT_EQ(p.at("spacecraft.J_kgm2").rows, 3);
    // Knowledge defaults to the nominal truth, as a separate parameter.
    EXPECT_EQ(p.get_matrix("knowledge.J_kgm2"), p.get_matrix("spacecraft.J_kgm2"));
    EXPECT_NE(p.at("knowledge.J_kgm2").source.find("default"), std::string::npos);
    EXPECT_EQ(p.at("controller.type").allowed, std::vector<std::string>{"mrp_pd"});
    EXPECT_TRUE(p.has("requirements.pointing_deg"));
  }
  const LoadedVehicle cubesat = load(example_path("cubesat-12u.toml"));
  EXPECT_EQ(cubesat.params.at("wheels.axes_B").rows, 4);
  EXPECT_EQ(cubesat.params.get_vector("wheels.friction_Nm_s"), std::vector<double>(4, 0.0));  // default
  EXPECT_TRUE(cubesat.params.has("knowledge.wheel_axes_B"));
  EXPECT_FALSE(cubesat.params.has("knowledge.cmg_h_Nms"));
  const LoadedVehicle imager = load(example_path("cmg-imager.toml"));
  EXPECT_EQ(imager.params.at("cmgs.gimbal_axes_B").rows, 4);
  EXPECT_EQ(imager.params.get_vector("reference.slews.1.sigma_RN")[2], 0.13165249758739583);
  EXPECT_EQ(imager.params.get_number("reference.slews.1.t_s"), 5.0);
  EXPECT_EQ(imager.params.get_name("cmgs.steering"), "escape");
  EXPECT_FALSE(imager.params.has("wheels.axes_B"));
}

TEST_F(VehicleLoader, SetChangesTheTruthNotTheKnowledge) {
  LoadedVehicle v = load(example_path("cubesat-12u.toml"), {{"spacecraft.J_kgm2", "[[0.22,0,0],[0,0.25,0],[0,0,0.15]]"}});
  EXPECT_EQ(v.params.get_matrix("spacecraft.J_kgm2")[0][0], 0.22);
  EXPECT_EQ(v.params.get_matrix("knowledge.J_kgm2")[0][0], 0.20);
}

TEST_F(VehicleLoader, MalformedTomlNamesItsLine) {
  expect_error(replaced("K_Nm", "K_Nm = = 0.1"), line("K_Nm"), "malformed TOML");
  expect_error(std::string(kMinimal) + "[run]\n", next(), "malformed TOML");  // a table defined twice
}

TEST_F(VehicleLoader, UnknownKeyOrTableNamesItsLine) {
  expect_error(replaced("duration_s", "durration_s = 2.0"), line("duration_s"), "unknown key 'durration_s' in [run]");
  expect_error(std::string(kMinimal) + "[sensor.gyro]\narw_rad_sqrt_s = 1e-5\n", next(), "unknown table 'sensor'");
  expect_error(std::string(kMinimal) + "[requirements]\npointing_deg = 0.1\nsettle = 10.0\n", next() + 2,
               "unknown key 'settle' in [requirements]");
  expect_error(replaced("name", "nmae = \"minimal\""), 1, "unknown key 'nmae' at the top level");
}

TEST_F(VehicleLoader, WrongTypeOrShapeNamesItsLine) {
  const int J = line("J_kgm2");
  expect_error(replaced("J_kgm2", "J_kgm2 = [[1.0, 0.0, 0.0], [0.0, 1.2, 0.0]]"), J, "spacecraft.J_kgm2: expected a 3x3 matrix");
  expect_error(replaced("J_kgm2", "J_kgm2 = [[1.0, 0.0], [0.0, 1.2], [0.0, 0.0]]"), J, "spacecraft.J_kgm2");
  expect_error(replaced("duration_s", "duration_s = \"two\""), line("duration_s"), "duration_s: expected a number, got a string");
  expect_error(replaced("J_s_kgm2", "J_s_kgm2 = [1e-3, 1e-3]"), line("J_s_kgm2"),
               "wheels.J_s_kgm2: expected a vector of 3 numbers (one per wheel)");
  expect_error(replaced("P_Nms", "P_Nms = 0.5"), line("P_Nms"), "controller.P_Nms: expected a vector of 3 numbers");
  expect_error(replaced("type = \"mrp_pd\"", "type = \"pid\""), line("type = \"mrp_pd\""), "'pid' is not one of: mrp_pd, ppc");
  expect_error(replaced("K_Nm", "K_Nm = nan"), line("K_Nm"), "finite");
  expect_error(std::string(kMinimal) + "[disturbances]\nharmonic = 3.0\n", next() + 1,
               "'disturbances.harmonic' must be a table [disturbances.harmonic], got a float");
}

TEST_F(VehicleLoader, NonUnitOrNonPerpendicularAxisIsRefused) {
  expect_error(replaced("axes_B", "axes_B = [[1.0, 0.01, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]"), line("axes_B"),
               "wheels.axes_B: row 1 must be a unit vector (within 1e-6)");
  // Within 1e-6: accepted (and normalised).
  const std::string ok = replaced("axes_B", "axes_B = [[1.0000005, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]");
  EXPECT_NO_THROW(adcs::sim::vehicle::load_vehicle_file(write_file(dir_, "ok.toml", ok)));
}

TEST_F(VehicleLoader, CmgSpinAxisMustBePerpendicularToItsGimbal) {
  const std::string cmg = R"(name = "cmg3"
description = "three CMGs"
[run]
duration_s = 1.0
control_period_s = 0.1
steady_window_s = [0.0, 1.0]
[spacecraft]
J_kgm2 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
[cmgs]
gimbal_axes_B = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
spin_axes_B = [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.6, 0.0, 0.8]]
h_Nms = [0.1, 0.1, 0.1]
gimbal_rate_max_rad_s = [1.0, 1.0, 1.0]
[controller]
type = "mrp_pd"
K_Nm = 0.1
P_Nms = [0.5, 0.5, 0.5]
[actuation]
type = "vscmg_steering"
[reference]
sigma_RN = [0.0, 0.0, 0.0]
)";
  expect_error(cmg, line_of(cmg, "spin_axes_B"), "cmgs.spin_axes_B: row 3 must be perpendicular to its gimbal axis");
  const std::string ok = replace_line(cmg, "spin_axes_B", "spin_axes_B = [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]");
  EXPECT_NO_THROW(adcs::sim::vehicle::load_vehicle_file(write_file(dir_, "ok.toml", ok)));
  // 2 CMGs and 1 wheel: not a supported set, named with the line of the CMG axes.
  std::string two = replace_line(ok, "gimbal_axes_B", "gimbal_axes_B = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]");
  two = replace_line(two, "spin_axes_B", "spin_axes_B = [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]");
  two = replace_line(two, "h_Nms", "h_Nms = [0.1, 0.1]");
  two = replace_line(two, "gimbal_rate_max_rad_s", "gimbal_rate_max_rad_s = [1.0, 1.0]");
  two += "[wheels]\naxes_B = [[0.0, 0.0, 1.0]]\nJ_s_kgm2 = [1e-3]\ntorque_max_Nm = [0.01]\nspeed_max_rad_s = [600.0]\n";
  expect_error(two, line_of(two, "gimbal_axes_B"),
               "2 CMGs and 1 wheel: unsupported actuator set (supported: 3, 4, 5 or 6 wheels; 3, 4, 5 or 6 CMGs; 4 CMGs + 3 wheels)");
}

TEST_F(VehicleLoader, UnsupportedWheelCountIsRefused) {
  const std::string two = replace_line(
      replace_line(replace_line(replace_line(kMinimal, "axes_B", "axes_B = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]"), "J_s_kgm2",
                                "J_s_kgm2 = [1e-3, 1e-3]"),
                   "torque_max_Nm", "torque_max_Nm = [0.01, 0.01]"),
      "speed_max_rad_s", "speed_max_rad_s = [600.0, 600.0]");
  expect_error(two, line("axes_B"), "2 wheels: unsupported actuator set");
  expect_error(two, line("axes_B"), "fewer than 3 wheels cannot give three-axis torque");
  const std::string seven = replaced("axes_B", "axes_B = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0], "
                                               "[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]");
  expect_error(seven, line("axes_B"), "7 wheels: unsupported actuator set");
  expect_error(drop_tables(kMinimal, {"[wheels]"}), 0, "0 wheels: unsupported actuator set");
}

TEST_F(VehicleLoader, MissingRequiredKeyOrTableIsNamed) {
  expect_error(replaced("K_Nm", ""), line("[controller]"), "[controller] is missing the required key 'K_Nm' [N m]");
  expect_error(replaced("steady_window_s", ""), line("[run]"), "[run] is missing the required key 'steady_window_s'");
  expect_error(replaced("description", ""), 0, "the top level is missing the required key 'description'");
  expect_error(drop_tables(kMinimal, {"[reference]"}), 0, "missing table [reference]");
  expect_error(replaced("axes_B", ""), line("[wheels]"), "[wheels] is missing the required key 'axes_B'");
  expect_error(std::string(kMinimal) + "[sensors.star_tracker]\nnoise_rad = 1e-5\n", next(),
               "[sensors.star_tracker] is missing the required key 'rate_hz'");
}

TEST_F(VehicleLoader, ValuesThatMakeNoSenseAreRefusedWithTheirLine) {
  expect_error(replaced("J_kgm2", "J_kgm2 = [[1.0, 0.0, 0.0], [0.0, 1.2, 0.0], [0.0, 0.0, 3.0]]"), line("J_kgm2"),
               "triangle inequality");
  expect_error(replaced("K_Nm", "K_Nm = -0.1"), line("K_Nm"), "controller.K_Nm: must be > 0");
  expect_error(replaced("axes_B", "axes_B = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.6, 0.8, 0.0]]"), line("axes_B"),
               "wheels.axes_B: the wheel axes must span three dimensions");
  expect_error(replaced("steady_window_s", "steady_window_s = [1.0, 3.0]"), line("steady_window_s"), "steady_window_s");
  expect_error(replaced("P_Nms", "P_Nms = [0.5, 0.5, 0.5]\nrho0_deg = [1.0, 1.0, 1.0]"), line("P_Nms") + 1,
               "controller.rho0_deg is a key of controller type ppc, not mrp_pd");
  expect_error(std::string(kMinimal) + "[sensors.star_tracker]\nnoise_rad = 1e-5\nrate_hz = 3.0\n", next() + 2,
               "3 Hz must equal or divide the control rate");
  expect_error(std::string(kMinimal) + "[requirements]\nsettle_s = 10.0\n", next() + 1, "needs requirements.pointing_deg");
  expect_error(replaced("name", "name = \"Minimal Vehicle\""), 1, "lower-case letters, digits and '-'");
  expect_error(replaced("type = \"rw_allocation\"", "type = \"vscmg_steering\""), line("type = \"rw_allocation\""),
               "needs [cmgs]");
  expect_error(std::string(kMinimal) + "[knowledge]\ncmg_h_Nms = [0.1, 0.1, 0.1]\n", next() + 1,
               "knowledge.cmg_h_Nms names actuators this vehicle does not have");
}

TEST_F(VehicleLoader, MissingFileIsAOneLineError) {
  const std::string path = (dir_ / "no-such-vehicle.toml").string();
  try {
    adcs::sim::vehicle::load_vehicle_file(path);
    ADD_FAILURE() << "no error";
  } catch (const ParamError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot open the vehicle file for reading");
  }
}

TEST_F(VehicleLoader, CommandLineValuesAreCheckedWhenRun) {
  const std::string path = write_file(dir_, "v.toml", kMinimal);
  LoadedVehicle v = load(path, {{"wheels.axes_B", "[[1,0.5,0],[0,1,0],[0,0,1]]"}});
  adcs::sim::RunContext ctx;
  try {
    v.scenario->run(v.params, ctx);
    ADD_FAILURE() << "no error";
  } catch (const ParamError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("wheels.axes_B (--set): row 1 must be a unit vector", 0), 0u) << e.what();
  }
  // The law and the actuation are fixed by the file.
  EXPECT_THROW(v.params.set("controller.type", "ppc"), ParamError);
}

// docs/VEHICLE-FILES.md documents every key of the schema.
TEST(VehicleDocs, EveryKeyIsDocumented) {
  const std::string doc = read_text(std::string(ADCS_SOURCE_DIR) + "/docs/VEHICLE-FILES.md");
  ASSERT_FALSE(doc.empty());
  for (const auto& k : adcs::sim::vehicle::key_specs())
    EXPECT_NE(doc.find("| `" + std::string(k.key) + "` |"), std::string::npos) << k.table << "." << k.key;
  for (const auto& t : adcs::sim::vehicle::table_specs())
    if (!t.path.empty() && t.path != "sensors") {
      EXPECT_NE(doc.find("[" + std::string(t.path) + "]"), std::string::npos) << t.path;
    }
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
