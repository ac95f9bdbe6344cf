// The component concept (core/component.hpp, issue 17): the checker accepts the shape and names
// each way of missing it. The negative cases are compile-time facts; a component that drifts from
// the shape fails ADCS_ASSERT_COMPONENT where it is declared.
#include <gtest/gtest.h>

#include <cmath>

#include "adcs/core/component.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/types.hpp"

namespace ADCS_UNITY_ID {
using adcs::Status;

// A minimal conforming component: a discrete integrator y += T u with a clamp, refusing NaN.
struct Integrator {
  struct Params {
    double period_s = 0.1;  //!< [s]
    double limit = 1.0;     //!< |y| <= limit
  };
  struct Input {
    double u = 0.0;
  };
  struct Output {
    double y = 0.0;
  };
  struct Diagnostics {
    bool clipped = false;
  };
  explicit Integrator(const Params& p) noexcept
      : p_(p), status_(p.period_s > 0.0 && p.limit > 0.0 ? Status::ok : Status::invalid_parameter) {}
  Status status() const noexcept { return status_; }
  void reset() noexcept { y_ = 0.0; }
  double period_s() const noexcept { return p_.period_s; }
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* d = nullptr) noexcept {
    out = Output{};  // the safe output: zero
    if (status_ != Status::ok) return status_;
    if (!std::isfinite(in.u)) return Status::non_finite_input;
    double y = y_ + p_.period_s * in.u;
    const bool clip = y > p_.limit || y < -p_.limit;
    if (clip) y = y > 0.0 ? p_.limit : -p_.limit;
    if (d) d->clipped = clip;
    y_ = y;
    out.y = y;
    return clip ? Status::saturated : Status::ok;
  }

 private:
  Params p_;
  double y_ = 0.0;
  Status status_;
};
ADCS_ASSERT_COMPONENT(Integrator);

// Each of these misses one part of the shape.
struct NoDiagnostics {
  struct Params {};
  struct Input {};
  struct Output {};
  explicit NoDiagnostics(const Params&) noexcept {}
  Status status() const noexcept { return Status::ok; }
  void reset() noexcept {}
  double period_s() const noexcept { return 1.0; }
  Status step(const Input&, Output&) noexcept { return Status::ok; }
};
struct ThrowingStep : Integrator {
  using Integrator::Integrator;
  Status step(const Input&, Output&, Diagnostics* = nullptr) { return Status::ok; }  // not noexcept
};
struct BoolStatus : Integrator {
  using Integrator::Integrator;
  bool status() const noexcept { return true; }
};
struct NoPeriod {
  using Params = Integrator::Params;
  using Input = Integrator::Input;
  using Output = Integrator::Output;
  using Diagnostics = Integrator::Diagnostics;
  explicit NoPeriod(const Params&) noexcept {}
  Status status() const noexcept { return Status::ok; }
  void reset() noexcept {}
  Status step(const Input&, Output&, Diagnostics* = nullptr) noexcept { return Status::ok; }
};
struct DiagnosticsRequired : Integrator {
  using Integrator::Integrator;
  Status step(const Input&, Output&, Diagnostics*) noexcept { return Status::ok; }
};
struct ThrowingConstructor : Integrator {
  explicit ThrowingConstructor(const Params& p) : Integrator(p) {}
};

static_assert(adcs::is_component_v<Integrator>);
static_assert(!adcs::is_component_v<NoDiagnostics> && !adcs::detail::has_types<NoDiagnostics>::value);
static_assert(!adcs::is_component_v<ThrowingStep> && !adcs::detail::has_step<ThrowingStep>::value);
static_assert(!adcs::is_component_v<BoolStatus> && !adcs::detail::has_status<BoolStatus>::value);
static_assert(!adcs::is_component_v<NoPeriod> && !adcs::detail::has_period<NoPeriod>::value);
static_assert(!adcs::is_component_v<DiagnosticsRequired> &&
              !adcs::detail::has_step_without_diagnostics<DiagnosticsRequired>::value);
static_assert(!adcs::is_component_v<ThrowingConstructor> &&
              !adcs::detail::constructible_from_params<ThrowingConstructor>::value);
static_assert(!adcs::is_component_v<int>);

// The conforming component behaves as the shape promises: refused parameters give the safe output
// and invalid_parameter; bad input gives the safe output and keeps the state.
TEST(Component, TheShapeAndItsFailureSemantics) {
  Integrator ok(Integrator::Params{0.5, 1.0});
  ASSERT_EQ(ok.status(), Status::ok);
  EXPECT_EQ(ok.period_s(), 0.5);
  Integrator::Output out;
  Integrator::Diagnostics d;
  EXPECT_EQ(ok.step(Integrator::Input{1.0}, out, &d), Status::ok);
  EXPECT_EQ(out.y, 0.5);
  EXPECT_EQ(ok.step(Integrator::Input{std::nan("")}, out), Status::non_finite_input);
  EXPECT_EQ(out.y, 0.0);  // safe output
  EXPECT_EQ(ok.step(Integrator::Input{2.0}, out, &d), Status::saturated);
  EXPECT_TRUE(d.clipped);
  EXPECT_EQ(out.y, 1.0);  // the state survived the rejected sample: 0.5 + 1.0, clipped to 1
  ok.reset();
  EXPECT_EQ(ok.step(Integrator::Input{0.0}, out), Status::ok);
  EXPECT_EQ(out.y, 0.0);
  Integrator bad(Integrator::Params{0.0, 1.0});
  EXPECT_EQ(bad.status(), Status::invalid_parameter);
  EXPECT_EQ(bad.step(Integrator::Input{1.0}, out), Status::invalid_parameter);
  EXPECT_EQ(out.y, 0.0);
}
}  // namespace

using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
