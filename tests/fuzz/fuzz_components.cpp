// libFuzzer harness over the one list of flight components (tests/components/component_list.hpp):
// a component added to the list is fuzzed with no code here.
//
// Byte format: byte 0 picks the component (index mod the list's size), byte 1 the number of
// steps (1 + b % 8); then, per step, one fuzz::Reader::value() per scalar of the component's
// Input (the Input seen as its array of scalars, double or float (the type period_s() returns):
// every Input of the list is made of scalars and fixed-size Eigen objects of them, checked by the
// static_assert below; a zero-size Eigen member only adds padding, which is never read; a float
// slot gets the value rounded to float, 1e300 becoming Inf), each ADDED to that
// slot of the nominal input ComponentFixture<C>::input(k): zero bytes leave the nominal
// operating point, NaN/Inf/1e300/denormals and raw doubles hit every field.
//
// Properties, for every component:
//   - every output is finite, whatever the status (the one failure semantics);
//   - a step whose status is not usable leaves the state untouched (kRejectionKeepsState): a
//     twin that is stepped only with the accepted inputs gives bit-identical outputs afterwards,
//     on three nominal steps;
//   - same inputs, same outputs: the twin's accepted steps match the fuzzed instance's.
#include <cmath>
#include <cstddef>
#include <limits>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "component_list.hpp"  // tests/components
#include "fuzz_common.hpp"

// File-local, and named: the five harnesses are compiled in one unit (tests/fuzz/CMakeLists.txt).
namespace ADCS_UNITY_ID {

//! v in the scalar S. A double beyond float's range becomes ±Inf, as IEEE rounding does: a plain
//! static_cast would be undefined behaviour there (UBSan's float-cast-overflow).
template <class S>
S to_scalar(double v) {
  if constexpr (std::is_same_v<S, double>) {
    return v;
  } else {
    if (std::isfinite(v) && std::abs(v) > static_cast<double>(std::numeric_limits<S>::max()))
      return std::copysign(std::numeric_limits<S>::infinity(), static_cast<S>(v > 0 ? 1 : -1));
    return static_cast<S>(v);
  }
}

template <class C>
void fuzz_one(fuzz::Reader& r, int steps) {
  using Fx = adcs::test::ComponentFixture<C>;
  using Input = typename C::Input;
  using Output = typename C::Output;
  using S = std::remove_cv_t<decltype(std::declval<const C&>().period_s())>;
  static_assert(sizeof(Input) % sizeof(S) == 0, "an Input is made of scalars");
  static const typename C::Params params = Fx::params();
  C a(params), b(params);
  FUZZ_CHECK(a.status() == adcs::Status::ok, "the fixture's parameters are refused");
  for (int k = 0; k < steps; ++k) {
    Input in = Fx::input(k);
    S* slot = reinterpret_cast<S*>(&in);
    for (std::size_t i = 0; i < sizeof(Input) / sizeof(S); ++i) slot[i] += to_scalar<S>(r.value());
    Output out_a{}, out_b{};
    const adcs::Status s = a.step(in, out_a);
    const adcs::test::OutputValues va(out_a);
    FUZZ_CHECK(va.finite(), Fx::name);
    if (adcs::usable(s)) {
      const adcs::Status sb = b.step(in, out_b);
      FUZZ_CHECK(sb == s && va.same_bits(adcs::test::OutputValues(out_b)), "same inputs, same outputs");
    } else if (!adcs::test::kRejectionKeepsState<C>) {
      return;  // an estimator coasting through a rejected measurement: the twins part here
    }
  }
  for (int k = 0; k < 3; ++k) {  // the rejected steps left nothing behind
    Output out_a{}, out_b{};
    const adcs::Status sa = a.step(Fx::input(100 + k), out_a), sb = b.step(Fx::input(100 + k), out_b);
    FUZZ_CHECK(sa == sb && adcs::test::OutputValues(out_a).same_bits(adcs::test::OutputValues(out_b)),
               "a rejected step changed the state");
  }
}

}  // namespace ADCS_UNITY_ID

ADCS_FUZZ_ENTRY(fuzz_components) {
  using namespace ADCS_UNITY_ID;
  fuzz::Reader r(data, size);
  constexpr int kCount = static_cast<int>(std::tuple_size_v<adcs::test::FlightComponentList>);
  const int pick = r.u8() % kCount;
  const int steps = 1 + r.u8() % 8;
  int i = 0;
  adcs::test::for_each_component([&](auto* type) {
    if (i++ == pick) fuzz_one<std::remove_pointer_t<decltype(type)>>(r, steps);
  });
  return 0;
}
