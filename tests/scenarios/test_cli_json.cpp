// What is ours in adcs-sim's JSON (nlohmann/json holds the documents): the number format, the
// layout, the escaping rules we keep, and the shape of the pieces every output is made of.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "cli/json_text.hpp"
#include "cli/run_json.hpp"

namespace adcs::sim::cli {
namespace ADCS_UNITY_ID {

TEST(Json, NumbersArePercent15gOr17gWhenThatIsNeededToReadBack) {
  EXPECT_EQ(json_number(1.0), "1");  // nlohmann's dump(): "1.0"
  EXPECT_EQ(json_number(-2.5), "-2.5");
  EXPECT_EQ(json_number(0.1), "0.1");
  EXPECT_EQ(json_number(1e-300), "1e-300");
  EXPECT_EQ(json_number(2e300), "2e+300");
  EXPECT_EQ(json_number(1e-5), "1e-05");
  EXPECT_EQ(json_number(1e20), "1e+20");
  EXPECT_EQ(json_number(0.1 + 0.7), "0.79999999999999993");  // dump(): 0.7999999999999999
  EXPECT_EQ(json_number(5e-324), "4.94065645841247e-324");  // dump(): 5e-324
  EXPECT_EQ(json_number(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(std::stod(json_number(1.0 / 3.0)), 1.0 / 3.0);
  EXPECT_EQ(json_number(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(json_number(std::numeric_limits<double>::infinity()), "null");
  EXPECT_EQ(json_number(-std::numeric_limits<double>::infinity()), "null");
}

TEST(Json, CompactTextKeepsMemberOrderAndOurSeparators) {
  Json j = Json::object();
  j["scenario"] = "x";
  j["seed"] = std::uint64_t{18446744073709551615ull};
  j["metrics"] = Json::object();
  j["metrics"]["b"] = 1.5;
  j["metrics"]["a"] = std::nan("");
  j["v"] = std::vector<double>{1, 2};
  j["m"] = std::vector<std::vector<double>>{{1, 0}, {0, 1}};
  j["e"] = Json::array();
  j["o"] = Json::object();
  j["t"] = true;
  j["h"] = nullptr;
  j["i"] = -3;
  EXPECT_EQ(json_text(j),
            R"j({"scenario": "x", "seed": 18446744073709551615, "metrics": {"b": 1.5, "a": null}, )j"
            R"j("v": [1, 2], "m": [[1, 0], [0, 1]], "e": [], "o": {}, "t": true, "h": null, "i": -3})j");
}

TEST(Json, PrettyToADepth) {
  Json j = Json::object();
  j["a"] = 1.0;
  j["b"] = Json{{"c", std::vector<double>{1, 2}}};
  j["e"] = Json::array();
  EXPECT_EQ(json_text(j, 1), "{\n  \"a\": 1,\n  \"b\": {\"c\": [1, 2]},\n  \"e\": []\n}");
  EXPECT_EQ(json_text(j, 2), "{\n  \"a\": 1,\n  \"b\": {\n    \"c\": [1, 2]\n  },\n  \"e\": []\n}");
  EXPECT_EQ(json_text(Json::object(), 2), "{}");
  EXPECT_EQ(json_text(Json::array({1.0, Json::array({2.0})}), 1), "[\n  1,\n  [2]\n]");
}

TEST(Json, Strings) {
  const auto text = [](const std::string& s) { return json_text(Json(s)); };
  EXPECT_EQ(text("a"), "\"a\"");
  EXPECT_EQ(text("q\"b\\/"), "\"q\\\"b\\\\/\"");
  EXPECT_EQ(text("l1\nl2\t\r\b\f"), "\"l1\\nl2\\t\\r\\b\\f\"");
  EXPECT_EQ(text(std::string("\x01\x1f", 2)), "\"\\u0001\\u001f\"");
  EXPECT_EQ(text("del\x7f" "del\x7f"), "\"del\\u007fdel\\u007f\"");  // as adcs-sim always wrote
  EXPECT_EQ(text("m\xc2\xb2 \xe2\x88\x9a"), "\"m\xc2\xb2 \xe2\x88\x9a\"");  // UTF-8 passes through
  EXPECT_EQ(text("bad\xff"), "\"bad\xef\xbf\xbd\"");  // not UTF-8: U+FFFD, still valid JSON
  Json keyed = Json::object();
  keyed["k\"\n"] = "v";
  EXPECT_EQ(json_text(keyed), R"j({"k\"\n": "v"})j");
}

TEST(RunJson, ParametersWithOverridesAndUsedValues) {
  ParamSet ps;
  ps.number("duration_s", 1.0, "s", "assumed: test");
  ps.vector("x0", {0.0, 0.0}, "m", "paper Table 9");
  ps.name("method", "adams", {"adams", "bdf"}, "assumed: test");
  ps.set("duration_s", "2");
  const std::vector<UsedValue> used = {
      UsedValue::vector("x0", {1.5, -2.0}, "", "drawn from --seed"),
      UsedValue::number("n", 20.0, "-", "derived"),
      UsedValue::number("n", 21.0, "-", "derived twice: the first is kept"),
  };
  EXPECT_EQ(json_text(parameters_json(ps, used)),
            R"j({"duration_s": {"value": 2, "unit": "s", "source": "command line (--set)", )j"
            R"j("default": 1, "default_source": "assumed: test"}, )j"
            R"j("x0": {"value": [1.5, -2], "unit": "m", "source": "drawn from --seed", )j"
            R"j("declared": [0, 0], "declared_source": "paper Table 9"}, )j"
            R"j("method": {"value": "adams", "unit": "", "source": "assumed: test"}, )j"
            R"j("n": {"value": 20, "unit": "-", "source": "derived"}})j");
}

TEST(RunJson, ClaimsAndPlots) {
  Claim paper{"paper", "c", "1", "2", std::nullopt, PaperVerdict::partly, "crit", "a note"};
  Claim check{"check", "d", "3", "4", false};
  EXPECT_EQ(json_text(claims_json({paper, check})),
            R"j([{"kind": "paper", "claim": "c", "paper_value": "1", "ours": "2", )j"
            R"j("paper_verdict": "partly", "criterion": "crit", "criterion_holds": null, "holds": null, )j"
            R"j("note": "a note"}, )j"
            R"j({"kind": "check", "claim": "d", "paper_value": "3", "ours": "4", "paper_verdict": null, )j"
            R"j("criterion": "", "criterion_holds": false, "holds": false}])j");
  PlotSpec full{"f.png", "t", "t", {"lo", "hi"}, "m", false};
  full.fill = {{"lo", "hi"}};
  full.csv = "extra.csv";
  full.kind = "psd";
  full.hline = {{0.5, "limit"}};
  EXPECT_EQ(json_text(plots_json({full})),
            R"j([{"file": "f.png", "title": "t", "x": "t", "y": ["lo", "hi"], "ylabel": "m", )j"
            R"j("logy": false, "fill": [["lo", "hi"]], "csv": "extra.csv", "kind": "psd", )j"
            R"j("hline": [[0.5, "limit"]]}])j");
}

TEST(RunJson, MonteCarloSummary) {
  const double nan = std::nan("");
  EXPECT_EQ(json_text(summary_json({"a", "b", "c"}, {{3, 1, 2, 10}, {nan, 1.0, nan}, {nan}})),
            R"j({"a": {"min": 1, "median": 2.5, "max": 10}, )j"
            R"j("b": {"min": 1, "median": 1, "max": 1, "nonfinite": 2}, )j"
            R"j("c": {"min": null, "median": null, "max": null, "nonfinite": 1}})j");
  EXPECT_EQ(json_text(metrics_json({{"z", 1.0}, {"a", std::nan("")}})), R"j({"z": 1, "a": null})j");
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
}  // namespace adcs::sim::cli
