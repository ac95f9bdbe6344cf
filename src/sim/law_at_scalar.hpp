#pragma once
// A flight law run in double or in float behind one double interface (issue 19, `--set
// scalar=float|double`): the law computes in its scalar, the plant stays double under the
// integrator, as on a single-precision flight computer flown in a double ground simulation. The
// scenario's closed loop, plant and integrators see this one component type and are compiled once;
// only the law is instantiated for both scalars (the hybrid scenario's float path had compiled the
// whole loop a second time: ~20 clang CPU-s more for that one file).
//
// The crossings: parameters and inputs go into the law's scalar by cast<S>() (beyond float range:
// ±Inf, core/types.hpp narrow_scalar, which the law refuses with a status), commands come back by
// cast<double>() (exact). Diagnostics stay the law's own, in the scalar that ran.
#include <utility>
#include <variant>

#include "adcs/core/component.hpp"
#include "adcs/core/status.hpp"

namespace adcs::sim {

//! Law<S>: the law in scalar S, e.g. `template <class S> using Law = HybridAdaptive<4, 3, S>;`.
//! Law<S>::Params and Input have cast<T>(), Law<S>::Output has cast<double>().
template <template <class> class Law>
class LawAtScalar {
 public:
  using Double = Law<double>;
  using Single = Law<float>;
  struct Params {
    typename Double::Params law;
    bool single = false;  //!< true: the law runs in float (its parameters rounded once, here)
  };
  using Input = typename Double::Input;
  using Output = typename Double::Output;
  //! The diagnostics of whichever law ran (the other stays default).
  struct Diagnostics {
    typename Double::Diagnostics as_double{};
    typename Single::Diagnostics as_single{};
  };

  explicit LawAtScalar(const Params& p) noexcept
      : law_(p.single ? Variant(std::in_place_index<1>, p.law.template cast<float>())
                      : Variant(std::in_place_index<0>, p.law)) {}

  bool single() const noexcept { return law_.index() == 1; }
  Status status() const noexcept {
    return visit([](const auto& law) noexcept { return law.status(); });
  }
  void reset() noexcept {
    visit([](auto& law) noexcept { law.reset(); });
  }
  double period_s() const noexcept {
    return visit([](const auto& law) noexcept { return static_cast<double>(law.period_s()); });
  }

  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    if (Double* law = std::get_if<0>(&law_)) return law->step(in, out, diag ? &diag->as_double : nullptr);
    Single& law = *std::get_if<1>(&law_);
    typename Single::Output out_single = out.template cast<float>();
    const Status s = law.step(in.template cast<float>(), out_single, diag ? &diag->as_single : nullptr);
    out = out_single.template cast<double>();
    return s;
  }

  //! f(law) on the law in the scalar it runs in; f must return the same type for both.
  template <class F>
  decltype(auto) visit(F&& f) noexcept {
    return single() ? f(*std::get_if<1>(&law_)) : f(*std::get_if<0>(&law_));
  }
  template <class F>
  decltype(auto) visit(F&& f) const noexcept {
    return single() ? f(*std::get_if<1>(&law_)) : f(*std::get_if<0>(&law_));
  }
  //! f(diagnostics) on the diagnostics of the law that ran.
  template <class F>
  decltype(auto) visit(const Diagnostics& d, F&& f) const noexcept {
    return single() ? f(d.as_single) : f(d.as_double);
  }

 private:
  using Variant = std::variant<Double, Single>;
  Variant law_;
};

}  // namespace adcs::sim
