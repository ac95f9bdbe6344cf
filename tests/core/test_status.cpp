// Core: Status helpers, the replaceable failure hook (Sophus-style) and all_finite().
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <string>

#include "adcs/core/failure_hook.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace ADCS_UNITY_ID {

using adcs::Status;

constexpr std::array<Status, 10> kAllStatuses = {
    Status::ok,           Status::non_finite_input,    Status::out_of_range,
    Status::singular,     Status::ill_conditioned,     Status::constraint_violated,
    Status::saturated,    Status::not_converged,       Status::invalid_parameter,
    Status::request_not_met,
};

// The helpers are constexpr: usable in compile-time tables.
static_assert(adcs::worst(Status::ok, Status::singular) == Status::singular);
static_assert(adcs::worst(Status::saturated, Status::singular) == Status::singular);
static_assert(adcs::usable(Status::ill_conditioned) && !adcs::usable(Status::singular));
static_assert(adcs::to_string(Status::ok)[0] == 'o');

TEST(Status, ToStringIsDistinctNonEmptyAndStable) {
  std::set<std::string> names;
  for (Status s : kAllStatuses) {
    const char* name = adcs::to_string(s);
    ASSERT_NE(name, nullptr);
    EXPECT_GT(std::strlen(name), 0u);
    EXPECT_STRNE(name, "unknown") << "status " << static_cast<int>(s) << " has no name";
    names.insert(name);
  }
  EXPECT_EQ(names.size(), kAllStatuses.size());
  // Names are part of the ground interface (logs, telemetry decoders): they equal the enumerators.
  EXPECT_STREQ(adcs::to_string(Status::ok), "ok");
  EXPECT_STREQ(adcs::to_string(Status::non_finite_input), "non_finite_input");
  EXPECT_STREQ(adcs::to_string(Status::out_of_range), "out_of_range");
  EXPECT_STREQ(adcs::to_string(Status::singular), "singular");
  EXPECT_STREQ(adcs::to_string(Status::ill_conditioned), "ill_conditioned");
  EXPECT_STREQ(adcs::to_string(Status::constraint_violated), "constraint_violated");
  EXPECT_STREQ(adcs::to_string(Status::saturated), "saturated");
  EXPECT_STREQ(adcs::to_string(Status::not_converged), "not_converged");
  EXPECT_STREQ(adcs::to_string(Status::invalid_parameter), "invalid_parameter");
  EXPECT_STREQ(adcs::to_string(Status::request_not_met), "request_not_met");
  // A corrupted value (e.g. from telemetry) still maps to a string.
  EXPECT_STREQ(adcs::to_string(static_cast<Status>(200)), "unknown");
}

TEST(Status, UsableSplitsDegradedFromHardFailures) {
  EXPECT_TRUE(adcs::usable(Status::ok));
  EXPECT_TRUE(adcs::usable(Status::ill_conditioned));
  EXPECT_TRUE(adcs::usable(Status::constraint_violated));
  EXPECT_TRUE(adcs::usable(Status::saturated));
  EXPECT_FALSE(adcs::usable(Status::non_finite_input));
  EXPECT_FALSE(adcs::usable(Status::out_of_range));
  EXPECT_FALSE(adcs::usable(Status::singular));
  EXPECT_FALSE(adcs::usable(Status::not_converged));
  EXPECT_FALSE(adcs::usable(Status::invalid_parameter));
  EXPECT_FALSE(adcs::usable(Status::request_not_met));
}

TEST(Status, WrittenIsUsableOrRequestNotMet) {
  for (Status s : kAllStatuses) {
    SCOPED_TRACE(adcs::to_string(s));
    EXPECT_EQ(adcs::written(s), adcs::usable(s) || s == Status::request_not_met);
  }
}

TEST(Status, NumericValuesAreStable) {
  // Logged and sent to the ground as numbers: a new status goes at the end.
  EXPECT_EQ(static_cast<int>(Status::invalid_parameter), 8);
  EXPECT_EQ(static_cast<int>(Status::request_not_met), 9);
}

TEST(Status, WorstKeepsTheHardFailure) {
  for (Status a : kAllStatuses) {
    EXPECT_EQ(adcs::worst(a, a), a);
    EXPECT_EQ(adcs::worst(Status::ok, a), a);
    EXPECT_EQ(adcs::worst(a, Status::ok), a);
    for (Status b : kAllStatuses) {
      const Status w = adcs::worst(a, b);
      SCOPED_TRACE(std::string(adcs::to_string(a)) + ", " + adcs::to_string(b));
      EXPECT_TRUE(w == a || w == b);
      // A failure is never lost, and a hard failure is never downgraded to a usable one.
      if (a != Status::ok || b != Status::ok) {
        EXPECT_NE(w, Status::ok);
      }
      if (!adcs::usable(a) || !adcs::usable(b)) {
        EXPECT_FALSE(adcs::usable(w));
      }
      // Among equally severe non-ok statuses the first one wins.
      if (a != Status::ok && adcs::usable(a) == adcs::usable(b)) {
        EXPECT_EQ(w, a);
      }
    }
  }
  // Accumulating over sub-steps in either order keeps the hard failure.
  Status acc = Status::ok;
  for (Status s : {Status::saturated, Status::singular, Status::ill_conditioned}) acc = adcs::worst(acc, s);
  EXPECT_EQ(acc, Status::singular);
}

// ---- failure hook --------------------------------------------------------------------------

struct Captured {
  int calls = 0;
  const char* file = nullptr;
  int line = 0;
  std::string message;
};
Captured g_captured;

void capturing_hook(const char* file, int line, const char* message) noexcept {
  ++g_captured.calls;
  g_captured.file = file;
  g_captured.line = line;
  g_captured.message = message;
}

// Restores whatever hook was installed before the test, even when an assertion fails.
class FailureHookTest : public ::testing::Test {
 protected:
  void SetUp() override {
    g_captured = Captured{};
    previous_ = adcs::set_failure_hook(nullptr);
  }
  void TearDown() override { (void)adcs::set_failure_hook(previous_); }
  adcs::FailureHook previous_ = nullptr;
};

TEST_F(FailureHookTest, InstalledHookReceivesFileLineAndMessage) {
  const adcs::FailureHook before = adcs::set_failure_hook(&capturing_hook);
  EXPECT_NE(before, nullptr);  // the default hook, never a null pointer
  const std::uint32_t default_count = adcs::default_failure_count();

  const int expected_line = __LINE__ + 1;
  const bool passed = ADCS_CHECK(1 + 1 == 3, "arithmetic is broken");
  EXPECT_FALSE(passed);
  EXPECT_EQ(g_captured.calls, 1);
  ASSERT_NE(g_captured.file, nullptr);
  EXPECT_NE(std::string(g_captured.file).find("test_status.cpp"), std::string::npos);
  EXPECT_EQ(g_captured.line, expected_line);
  EXPECT_EQ(g_captured.message, "arithmetic is broken");
  // A custom hook replaces the default one: the default counter does not move.
  EXPECT_EQ(adcs::default_failure_count(), default_count);

  // set_failure_hook returns the previously installed hook.
  EXPECT_EQ(adcs::set_failure_hook(nullptr), &capturing_hook);
}

TEST_F(FailureHookTest, PassingCheckDoesNotCallTheHookAndEvaluatesConditionOnce) {
  (void)adcs::set_failure_hook(&capturing_hook);
  int evaluations = 0;
  const bool passed = ADCS_CHECK((++evaluations, true), "never reported");
  EXPECT_TRUE(passed);
  EXPECT_EQ(evaluations, 1);
  EXPECT_EQ(g_captured.calls, 0);

  const bool failed = ADCS_CHECK((++evaluations, false), "reported once");
  EXPECT_FALSE(failed);
  EXPECT_EQ(evaluations, 2);
  EXPECT_EQ(g_captured.calls, 1);
}

TEST_F(FailureHookTest, NullptrRestoresTheCountingDefault) {
  (void)adcs::set_failure_hook(&capturing_hook);
  const adcs::FailureHook replaced = adcs::set_failure_hook(nullptr);
  EXPECT_EQ(replaced, &capturing_hook);

  const std::uint32_t before = adcs::default_failure_count();
  const bool ok1 = ADCS_CHECK(false, "first");
  const bool ok2 = ADCS_CHECK(false, "second");
  const bool ok3 = ADCS_CHECK(true, "not a failure");
  EXPECT_FALSE(ok1);
  EXPECT_FALSE(ok2);
  EXPECT_TRUE(ok3);
  EXPECT_EQ(adcs::default_failure_count(), before + 2u);
  EXPECT_EQ(g_captured.calls, 0);  // the removed hook is no longer called

  // report_failure goes through the same slot.
  adcs::report_failure(__FILE__, __LINE__, "direct");
  EXPECT_EQ(adcs::default_failure_count(), before + 3u);
}

TEST_F(FailureHookTest, CheckWorksAsAStatementAndInConditions) {
  (void)adcs::set_failure_hook(&capturing_hook);
  // The way flight code uses it: guard clause returning a Status.
  auto validate = [](double mass) -> Status {
    if (!ADCS_CHECK(mass > 0.0, "mass must be positive")) return Status::invalid_parameter;
    return Status::ok;
  };
  EXPECT_EQ(validate(1.0), Status::ok);
  EXPECT_EQ(g_captured.calls, 0);
  EXPECT_EQ(validate(-1.0), Status::invalid_parameter);
  EXPECT_EQ(g_captured.calls, 1);
  EXPECT_EQ(g_captured.message, "mass must be positive");
}

// ---- all_finite ------------------------------------------------------------------------------

TEST(AllFinite, DetectsNanAndInfInEveryPosition) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const adcs::Mat<3, 4> base = adcs::Mat<3, 4>::Constant(1.5);
  EXPECT_TRUE(adcs::all_finite(base));
  EXPECT_TRUE(adcs::all_finite(adcs::Mat<3, 4>::Zero()));
  const adcs::Mat<3, 4> big = adcs::Mat<3, 4>::Constant(std::numeric_limits<double>::max());
  EXPECT_TRUE(adcs::all_finite(big));
  EXPECT_TRUE(adcs::all_finite(adcs::Mat<3, 4>::Constant(std::numeric_limits<double>::denorm_min())));
  for (double bad : {nan, inf, -inf}) {
    for (Eigen::Index i = 0; i < base.rows(); ++i) {
      for (Eigen::Index j = 0; j < base.cols(); ++j) {
        adcs::Mat<3, 4> m = base;
        m(i, j) = bad;
        EXPECT_FALSE(adcs::all_finite(m)) << "(" << i << "," << j << ") = " << bad;
        EXPECT_FALSE(adcs::all_finite(m.transpose()));  // expressions work too
        EXPECT_FALSE(adcs::all_finite(m.col(j)));
        EXPECT_TRUE(adcs::all_finite(m.col((j + 1) % 4)));
      }
    }
  }
  // An expression that overflows is caught, not its finite operands.
  EXPECT_FALSE(adcs::all_finite(big * 2.0));
  EXPECT_TRUE(adcs::all_finite(adcs::Vec3(1.0, -2.0, 3.0)));
  EXPECT_FALSE(adcs::all_finite(adcs::Vec3(1.0, nan, 3.0)));

  EXPECT_TRUE(adcs::all_finite(0.0));
  EXPECT_TRUE(adcs::all_finite(-1e308));
  EXPECT_FALSE(adcs::all_finite(nan));
  EXPECT_FALSE(adcs::all_finite(inf));
  EXPECT_FALSE(adcs::all_finite(-inf));
}

}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
