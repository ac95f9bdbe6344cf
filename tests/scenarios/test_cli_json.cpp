// The JSON writer used for every adcs-sim output.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "cli/json.hpp"

namespace adcs::sim::cli {
namespace {

TEST(Json, Strings) {
  EXPECT_EQ(json_string("a"), "\"a\"");
  EXPECT_EQ(json_string("q\"b\\"), "\"q\\\"b\\\\\"");
  EXPECT_EQ(json_string("l1\nl2\t\r"), "\"l1\\nl2\\t\\r\"");
  EXPECT_EQ(json_string(std::string("\x01", 1)), "\"\\u0001\"");
  EXPECT_EQ(json_string("m\xc2\xb2"), "\"m\xc2\xb2\"");  // UTF-8 passes through
}

TEST(Json, Numbers) {
  EXPECT_EQ(json_number(1.0), "1");
  EXPECT_EQ(json_number(-2.5), "-2.5");
  EXPECT_EQ(json_number(0.1), "0.1");
  EXPECT_EQ(json_number(1e-300), "1e-300");
  EXPECT_EQ(std::stod(json_number(1.0 / 3.0)), 1.0 / 3.0);
  EXPECT_EQ(std::stod(json_number(0.1 + 0.2)), 0.1 + 0.2);
  EXPECT_EQ(json_number(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(json_number(std::numeric_limits<double>::infinity()), "null");
  EXPECT_EQ(json_number(-std::numeric_limits<double>::infinity()), "null");
}

TEST(Json, CompactDocument) {
  JsonWriter w;
  w.begin_object();
  w.key("scenario").value("x");
  w.key("seed").value(std::uint64_t{18446744073709551615ull});
  w.key("metrics").begin_object();
  w.key("a").value(1.5);
  w.key("b").value(std::nan(""));
  w.end_object();
  w.key("v").value(std::vector<double>{1, 2});
  w.key("m").value(std::vector<std::vector<double>>{{1, 0}, {0, 1}});
  w.key("e").begin_array().end_array();
  w.key("t").value(true);
  w.key("h").value(std::optional<bool>{});
  w.end_object();
  EXPECT_TRUE(w.complete());
  EXPECT_EQ(w.str(),
            R"({"scenario": "x", "seed": 18446744073709551615, "metrics": {"a": 1.5, "b": null}, )"
            R"("v": [1, 2], "m": [[1, 0], [0, 1]], "e": [], "t": true, "h": null})");
}

TEST(Json, PrettyToADepth) {
  JsonWriter w(1);
  w.begin_object();
  w.key("a").value(1);
  w.key("b").begin_object().key("c").value(std::vector<double>{1, 2}).end_object();
  w.end_object();
  EXPECT_EQ(w.str(), "{\n  \"a\": 1,\n  \"b\": {\"c\": [1, 2]}\n}");
}

TEST(Json, MisuseThrows) {
  JsonWriter w;
  EXPECT_THROW(w.key("x"), std::logic_error);
  w.begin_object();
  EXPECT_THROW(w.value(1), std::logic_error);  // no key
  EXPECT_THROW(w.end_array(), std::logic_error);
  w.key("k");
  EXPECT_THROW(w.end_object(), std::logic_error);  // dangling key
  w.value(2).end_object();
  EXPECT_THROW(w.value(3), std::logic_error);  // second root
}

}  // namespace
}  // namespace adcs::sim::cli
