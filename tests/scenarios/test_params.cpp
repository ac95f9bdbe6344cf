// ParamSet: declaration, the --set value parser, typed getters, rejections.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "scenarios/scenario.hpp"

namespace adcs::sim {
namespace ADCS_UNITY_ID {

ParamSet make() {
  ParamSet p;
  p.number("duration_s", 10.0, "s", "assumed");
  p.number("control_period_s", 0.1, "s", "assumed");
  p.vector("x0", {1.0, 2.0, 3.0}, "rad", "paper Table 1");
  p.vector_any("list", {}, "-", "assumed");
  p.matrix("J", {{1.0, 0.0}, {0.0, 2.0}}, "kg m^2", "paper eq. 3");
  p.matrix("row", {{1.0, 2.0, 3.0}}, "-", "assumed");
  p.name("integrator", "adams", {"adams", "bdf"}, "assumed");
  p.name("label", "free", {}, "assumed");
  return p;
}

void expect_rejected(const std::string& key, const std::string& text) {
  ParamSet p = make();
  EXPECT_THROW(p.set(key, text), ParamError) << key << "=" << text;
}

TEST(Params, DefaultsAndDeclarationOrder) {
  const ParamSet p = make();
  std::vector<std::string> keys;
  for (const Param& q : p) keys.push_back(q.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"duration_s", "control_period_s", "x0", "list", "J",
                                            "row", "integrator", "label"}));
  EXPECT_EQ(p.size(), 8u);
  EXPECT_DOUBLE_EQ(p.get_number("duration_s"), 10.0);
  EXPECT_EQ(p.get_vector("x0"), (std::vector<double>{1, 2, 3}));
  EXPECT_TRUE(p.get_vector("list").empty());
  EXPECT_EQ(p.get_matrix("J"), (std::vector<std::vector<double>>{{1, 0}, {0, 2}}));
  EXPECT_EQ(p.get_name("integrator"), "adams");
  EXPECT_EQ(p.at("x0").unit, "rad");
  EXPECT_EQ(p.at("x0").source, "paper Table 1");
  EXPECT_EQ(p.at("x0").size, 3);
  EXPECT_EQ(p.at("list").size, -1);
  EXPECT_EQ(p.at("J").rows, 2);
  EXPECT_EQ(p.at("J").cols, 2);
  EXPECT_TRUE(p.has("J"));
  EXPECT_FALSE(p.has("K"));
  for (const Param& q : p) EXPECT_FALSE(q.overridden);
}

TEST(Params, Numbers) {
  ParamSet p = make();
  const std::pair<const char*, double> cases[] = {
      {"1e-3", 1e-3}, {"-2", -2.0}, {"0.5", 0.5}, {"+.5", 0.5}, {"3.", 3.0}, {"  7  ", 7.0},
      {"1E+2", 100.0}, {"-0", -0.0}, {"1e-400", 0.0}, {"0.1", 0.1}, {"123456789012", 123456789012.0}};
  for (const auto& [text, want] : cases) {
    p.set("duration_s", text);
    EXPECT_DOUBLE_EQ(p.get_number("duration_s"), want) << text;
  }
  EXPECT_TRUE(p.at("duration_s").overridden);
  EXPECT_FALSE(p.at("control_period_s").overridden);
  EXPECT_DOUBLE_EQ(p.at("duration_s").default_value.number, 10.0);
}

TEST(Params, Vectors) {
  ParamSet p = make();
  p.set("x0", "[4,5,6]");
  EXPECT_EQ(p.get_vector("x0"), (std::vector<double>{4, 5, 6}));
  p.set("x0", " [ -1e-3 , 0.5,\t2 ] ");
  EXPECT_EQ(p.get_vector("x0"), (std::vector<double>{-1e-3, 0.5, 2}));
  p.set("list", "[1]");
  EXPECT_EQ(p.get_vector("list"), (std::vector<double>{1}));
  p.set("list", "[1,2,3,4,5]");
  EXPECT_EQ(p.get_vector("list").size(), 5u);
  p.set("list", "[ ]");
  EXPECT_TRUE(p.get_vector("list").empty());
  EXPECT_EQ(p.at("x0").default_value.vector, (std::vector<double>{1, 2, 3}));
}

TEST(Params, Matrices) {
  ParamSet p = make();
  p.set("J", "[[1,2],[3,4]]");
  EXPECT_EQ(p.get_matrix("J"), (std::vector<std::vector<double>>{{1, 2}, {3, 4}}));
  p.set("J", " [ [ 5 , 6 ] , [ 7 , 8 ] ] ");
  const auto m = p.get_mat<2, 2>("J");
  EXPECT_EQ(m(0, 1), 6.0);  // row-major text
  EXPECT_EQ(m(1, 0), 7.0);
  p.set("row", "[[7,8,9]]");
  const auto r = p.get_mat<1, 3>("row");
  EXPECT_EQ(r(0, 2), 9.0);
}

TEST(Params, Names) {
  ParamSet p = make();
  p.set("integrator", "bdf");
  EXPECT_EQ(p.get_name("integrator"), "bdf");
  p.set("label", "sr-inverse_2.b");
  EXPECT_EQ(p.get_name("label"), "sr-inverse_2.b");
  p.set("label", " x ");
  EXPECT_EQ(p.get_name("label"), "x");
}

TEST(Params, TypedEigenGetters) {
  ParamSet p = make();
  const Eigen::Vector3d v = p.get_vec<3>("x0");
  EXPECT_EQ(v, Eigen::Vector3d(1, 2, 3));
  EXPECT_THROW(p.get_vec<4>("x0"), ParamError);
  EXPECT_THROW((p.get_mat<3, 2>("J")), ParamError);
  EXPECT_THROW((p.get_mat<2, 1>("J")), ParamError);
  p.set("list", "[1,2]");
  EXPECT_EQ(p.get_vec<Eigen::Dynamic>("list").size(), 2);
  EXPECT_EQ(p.get_vec<2>("list")(1), 2.0);
  EXPECT_THROW(p.get_vec<3>("list"), ParamError);  // user gave the wrong length
}

TEST(Params, GettersCheckKindAndKey) {
  const ParamSet p = make();
  EXPECT_THROW(p.get_number("x0"), std::logic_error);
  EXPECT_THROW(p.get_vector("duration_s"), std::logic_error);
  EXPECT_THROW(p.get_matrix("x0"), std::logic_error);
  EXPECT_THROW(p.get_name("J"), std::logic_error);
  EXPECT_THROW(p.get_number("nope"), std::logic_error);
  EXPECT_THROW(p.at("nope"), std::logic_error);
}

TEST(Params, RejectsUnknownKey) {
  ParamSet p = make();
  try {
    p.set("duration", "1");
    FAIL() << "no throw";
  } catch (const ParamError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("unknown parameter 'duration'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("duration_s"), std::string::npos) << msg;  // suggestion
  }
}

TEST(Params, RejectsMalformedNumbers) {
  for (const char* t : {"", "  ", "abc", "1,2", "1 2", "1e", "1e+", "1.2.3", "--1", "+-1", "1x",
                        "0x10", ".", "-", "e5", "1e5e5", "1_000", "[1]", "[[1]]", "1]", "(1)"})
    expect_rejected("duration_s", t);
}

TEST(Params, RejectsNonFinite) {
  for (const char* t : {"nan", "NaN", "inf", "-inf", "+inf", "Infinity", "-Infinity", "1e999",
                        "-1e400", "[1,nan,2]", "[inf,1,1]", "[[1,nan],[1,1]]"}) {
    expect_rejected(std::string(t).front() == '[' && std::string(t)[1] == '['
                        ? "J"
                        : (std::string(t).front() == '[' ? "x0" : "duration_s"),
                    t);
  }
  // Not even as a free name.
  expect_rejected("label", "nan");
  expect_rejected("label", "inf");
}

TEST(Params, RejectsMalformedVectors) {
  for (const char* t : {"[1,2", "[1,2,3", "1,2,3", "[1,,3]", "[,1,2,3]", "[1,2,3,]", "[1 2 3]",
                        "[1,2,3]]", "[1,2,3] x", "[1,2,3]4", "[1,[2],3]", "[[1,2,3]]", "[a,b,c]",
                        "[", "]", "[1;2;3]"})
    expect_rejected("x0", t);
}

TEST(Params, RejectsWrongVectorSize) {
  for (const char* t : {"[1,2]", "[1,2,3,4]", "[]", "[1]"}) expect_rejected("x0", t);
  ParamSet p = make();
  try {
    p.set("x0", "[1,2]");
    FAIL();
  } catch (const ParamError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("3"), std::string::npos) << msg;
    EXPECT_NE(msg.find("x0"), std::string::npos) << msg;
  }
  EXPECT_EQ(p.get_vector("x0"), (std::vector<double>{1, 2, 3}));  // unchanged
  EXPECT_FALSE(p.at("x0").overridden);
}

TEST(Params, RejectsBadMatrices) {
  for (const char* t : {"[[1,2],[3]]", "[[1,2],[3,4],[5,6]]", "[[1,2]]", "[[1],[2]]",
                        "[1,2,3,4]", "[[1,2],[3,4]", "[[1,2],,[3,4]]", "[[1,2],[3,4],]",
                        "[[1,2],3]", "[[1,2] [3,4]]", "[[[1,2]],[3,4]]", "[[],[]]", "[[1,,2],[3,4]]",
                        "2", "[[1,2],[3,4]] x", "eye"})
    expect_rejected("J", t);
  expect_rejected("row", "[1,2,3]");  // a 1x3 matrix wants [[..]]
}

TEST(Params, RejectsBadNames) {
  for (const char* t : {"rk4", "Adams", "1", "[1]", "adams bdf", "adams,", "", "'adams'", "\"bdf\""})
    expect_rejected("integrator", t);
  for (const char* t : {"2x", "-x", "x y", "[x]", "x!"}) expect_rejected("label", t);
  expect_rejected("duration_s", "adams");  // a name is not a number
  expect_rejected("x0", "adams");
}

TEST(Params, ParseValueShapes) {
  EXPECT_EQ(parse_value("1").shape, ParsedValue::Shape::number);
  EXPECT_EQ(parse_value("[1]").shape, ParsedValue::Shape::vector);
  EXPECT_EQ(parse_value("[]").shape, ParsedValue::Shape::vector);
  EXPECT_EQ(parse_value("[[1]]").shape, ParsedValue::Shape::matrix);
  EXPECT_EQ(parse_value("bdf").shape, ParsedValue::Shape::name);
}

TEST(Params, DeclarationMistakesAreLogicErrors) {
  ParamSet p;
  p.number("a", 1.0, "-", "s");
  EXPECT_THROW(p.number("a", 1.0, "-", "s"), std::logic_error);  // twice
  EXPECT_THROW(p.number("b c", 1.0, "-", "s"), std::logic_error);
  EXPECT_THROW(p.number("", 1.0, "-", "s"), std::logic_error);
  EXPECT_THROW(p.number("n", std::nan(""), "-", "s"), std::logic_error);
  EXPECT_THROW(p.vector("v", {}, "-", "s"), std::logic_error);
  EXPECT_THROW(p.matrix("m", {{1, 2}, {3}}, "-", "s"), std::logic_error);
  EXPECT_THROW(p.matrix("m", {}, "-", "s"), std::logic_error);
  EXPECT_THROW(p.name("k", "rk4", {"adams", "bdf"}, "s"), std::logic_error);
  EXPECT_THROW(p.name("k", "not a name", {}, "s"), std::logic_error);
  EXPECT_EQ(p.size(), 1u);
}

TEST(Params, FormatValue) {
  ParamSet p = make();
  EXPECT_EQ(format_value(p.at("duration_s")), "10");
  EXPECT_EQ(format_value(p.at("x0")), "[1, 2, 3]");
  EXPECT_EQ(format_value(p.at("J")), "[[1, 0], [0, 2]]");
  EXPECT_EQ(format_value(p.at("integrator")), "adams");
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(std::stod(format_number(1.0 / 3.0)), 1.0 / 3.0);  // round-trips
  // The formatted text parses back to the same value.
  p.set("J", "[[0.1, -2e-7], [3, 4.25]]");
  ParamSet q = make();
  q.set("J", format_value(p.at("J")));
  EXPECT_EQ(q.get_matrix("J"), p.get_matrix("J"));
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
}  // namespace adcs::sim
