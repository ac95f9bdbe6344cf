// The component contract (include/adcs/core/component.hpp), checked at run time over the one
// list of flight components (component_fixtures.hpp), as manif's typed suites check every group:
// a valid set constructs and reports its period; steps give finite outputs; a poisoned input is
// rejected (not usable), the output stays finite and the component's state is untouched (its
// next steps are bit-identical to a twin's that never saw the bad input); reset() brings back
// the behaviour of a fresh instance, bit for bit. The compile-time half is the static_asserts of
// ADCS_ASSERT_COMPONENT in every header and IsAComponent below.
#include <gtest/gtest.h>

#include <vector>

#include "component_fixtures.hpp"

namespace ADCS_UNITY_ID {

using adcs::test::OutputValues;  // a component's output as numbers (component_list.hpp)

template <class C>
class ComponentContract : public ::testing::Test {
 protected:
  using Fx = adcs::test::ComponentFixture<C>;
  //! Outputs of `c` over inputs first..last−1 (asserting each step usable and finite).
  static std::vector<OutputValues> run(C& c, int first, int last) {
    std::vector<OutputValues> outs;
    for (int k = first; k < last; ++k) {
      typename C::Output out{};
      typename C::Diagnostics diag{};
      const adcs::Status s = c.step(Fx::input(k), out, &diag);
      EXPECT_TRUE(adcs::usable(s)) << "step " << k << ": " << adcs::to_string(s);
      outs.emplace_back(out);
      EXPECT_TRUE(outs.back().finite()) << "step " << k;
    }
    return outs;
  }
};
TYPED_TEST_SUITE(ComponentContract, adcs::test::FlightComponents, adcs::test::ComponentNames);

TYPED_TEST(ComponentContract, IsAComponent) {
  static_assert(adcs::is_component_v<TypeParam>, "every listed component has the shape of core/component.hpp");
  SUCCEED();
}

TYPED_TEST(ComponentContract, ConstructsFromItsParamsAndReportsItsPeriod) {
  const TypeParam c(TestFixture::Fx::params());
  EXPECT_EQ(c.status(), adcs::Status::ok);
  EXPECT_TRUE(std::isfinite(c.period_s()));
  EXPECT_GE(c.period_s(), 0.0);  // 0: a memoryless actuation stage
}

TYPED_TEST(ComponentContract, RejectedInputLeavesStateUntouchedAndOutputFinite) {
  using Fx = typename TestFixture::Fx;
  TypeParam a(Fx::params()), b(Fx::params());
  TestFixture::run(a, 0, 10);
  TestFixture::run(b, 0, 10);
  typename TypeParam::Input bad = Fx::input(10);
  Fx::poison(bad);
  typename TypeParam::Output out{};
  const adcs::Status s = a.step(bad, out);
  EXPECT_FALSE(adcs::usable(s)) << adcs::to_string(s);
  EXPECT_TRUE(OutputValues(out).finite());
  // With the diagnostics requested too: the same answer.
  typename TypeParam::Diagnostics diag{};
  EXPECT_EQ(a.step(bad, out, &diag), s);
  const auto after_a = TestFixture::run(a, 10, 20), after_b = TestFixture::run(b, 10, 20);
  ASSERT_EQ(after_a.size(), after_b.size());
  for (std::size_t k = 0; k < after_a.size(); ++k) EXPECT_TRUE(after_a[k].same_bits(after_b[k])) << "step " << 10 + k;
}

TYPED_TEST(ComponentContract, ResetBringsBackAFreshInstance) {
  using Fx = typename TestFixture::Fx;
  TypeParam used(Fx::params()), fresh(Fx::params());
  TestFixture::run(used, 0, 20);
  used.reset();
  const auto a = TestFixture::run(used, 0, 10), b = TestFixture::run(fresh, 0, 10);
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_TRUE(a[k].same_bits(b[k])) << "step " << k;
}

TYPED_TEST(ComponentContract, SameInputsSameOutputsBitForBit) {
  using Fx = typename TestFixture::Fx;
  TypeParam a(Fx::params()), b(Fx::params());
  const auto oa = TestFixture::run(a, 0, 15), ob = TestFixture::run(b, 0, 15);
  for (std::size_t k = 0; k < oa.size(); ++k) EXPECT_TRUE(oa[k].same_bits(ob[k])) << "step " << k;
}

}  // namespace ADCS_UNITY_ID
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
