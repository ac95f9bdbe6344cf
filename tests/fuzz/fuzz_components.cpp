// libFuzzer harness over the one list of flight components (tests/components/component_list.hpp):
// a component added to the list is fuzzed with no code here.
//
// Byte format: byte 0 picks the component (index mod the list's size), byte 1 the number of
// steps (1 + b % 8); then, per step, one fuzz::Reader::value() per double of the component's
// Input (the Input seen as its array of doubles: every Input of the list is made of doubles and
// fixed-size Eigen objects of doubles, checked by the static_assert below; a zero-size Eigen
// member only adds padding, which is never read), each ADDED to that
// slot of the nominal input ComponentFixture<C>::input(k): zero bytes leave the nominal
// operating point, NaN/Inf/1e300/denormals and raw doubles hit every field.
//
// Properties, for every component:
//   - every output is finite, whatever the status (the one failure semantics);
//   - a step whose status is not usable leaves the state untouched (kRejectionKeepsState): a
//     twin that is stepped only with the accepted inputs gives bit-identical outputs afterwards,
//     on three nominal steps;
//   - same inputs, same outputs: the twin's accepted steps match the fuzzed instance's.
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "component_list.hpp"  // tests/components
#include "fuzz_common.hpp"

namespace {

template <class C>
void fuzz_one(fuzz::Reader& r, int steps) {
  using Fx = adcs::test::ComponentFixture<C>;
  using Input = typename C::Input;
  using Output = typename C::Output;
  static_assert(sizeof(Input) % sizeof(double) == 0, "an Input is made of doubles");
  static const typename C::Params params = Fx::params();
  C a(params), b(params);
  FUZZ_CHECK(a.status() == adcs::Status::ok, "the fixture's parameters are refused");
  for (int k = 0; k < steps; ++k) {
    Input in = Fx::input(k);
    double* slot = reinterpret_cast<double*>(&in);
    for (std::size_t i = 0; i < sizeof(Input) / sizeof(double); ++i) slot[i] += r.value();
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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
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
