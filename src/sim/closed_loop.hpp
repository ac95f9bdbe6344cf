#pragma once
// One generic closed loop (issue 17): any plant (core/plant.hpp) driven by any torque law through
// any actuation stage (core/component.hpp), sampled with a zero-order hold (sim/sampled_data.hpp),
// with the integrator chosen in one place (IntegratorChoice):
//
//   at t_k:  controller.step(sensors(t_k, x), cmd)                 the law, at its sample period
//            actuation.step(to_actuation(t_k, x, cmd), act)        allocation / steering / sat → Q
//            to_plant(t_k, x, act, u)                              actuator output → plant input
//            observer(sample)                                      metrics, CSV rows
//            integrate x over [t_k, t_k+1] with u held
//
// `sensors` is the measurement model (perfect, or with noise and dropouts: the loop does not
// care), called with (t, x) or, when it takes it, (t, x, u_held): the input held since the last
// sample; `to_actuation` feeds the stage what it needs besides the command (gimbal angles, the
// sample time); `to_plant` maps the actuator output into the plant's held input (and may add a
// disturbance the plant models as an input). Scenarios become compositions of these pieces.
#include <string>
#include <type_traits>
#include <utility>

#include "adcs/core/component.hpp"
#include "adcs/core/plant.hpp"
#include "sim/cvode_integrator.hpp"
#include "sim/rk4_integrator.hpp"
#include "sim/sampled_data.hpp"

namespace adcs::sim {

//! Which integrator advances the plant between samples, chosen once for a run.
struct IntegratorChoice {
  enum class Kind { adams, bdf, rk4 };
  Kind kind = Kind::adams;  //!< adams: CVODE Adams + fixed point; bdf: CVODE BDF + dense; rk4: fixed step
  double rtol = 1e-10;      //!< CVODE relative tolerance
  double atol = 1e-12;      //!< CVODE absolute tolerance
  double rk4_step_s = 0.01; //!< [s] RK4 maximum sub-step
};

//! Calls `body(integrator)` with the integrator `choice` selects for `plant` (a generic lambda
//! receives the concrete type).
template <class Plant, class Body>
void with_integrator(const Plant& plant, const IntegratorChoice& choice, Body&& body) {
  if (choice.kind == IntegratorChoice::Kind::rk4) {
    Rk4Integrator<Plant> integrator(plant, choice.rk4_step_s);
    body(integrator);
    return;
  }
  CvodeOptions options;
  options.method = choice.kind == IntegratorChoice::Kind::bdf ? CvodeOptions::Method::bdf_dense
                                                              : CvodeOptions::Method::adams_fixed_point;
  options.rtol = choice.rtol;
  options.atol = choice.atol;
  CvodeIntegrator<Plant> integrator(plant, options);
  body(integrator);
}

//! Calls the measurement model: sensors(t, x, u_held) when it reads the held plant input (a
//! momentum-form plant's body rate depends on the gimbal rates held over the last period), else
//! sensors(t, x).
template <class Sensors, class State, class Input>
decltype(auto) sense(Sensors& sensors, double t, const State& x, const Input& u_held) {
  if constexpr (std::is_invocable_v<Sensors&, double, const State&, const Input&>)
    return sensors(t, x, u_held);
  else
    return sensors(t, x);
}

//! What the observer sees at each sample (and once more at t_end with the last command).
template <class Plant, class Controller, class Actuation>
struct LoopSample {
  double t_s;                                        //!< [s]
  const typename Plant::State& x;                    //!< true state
  const typename Plant::Input& u;                    //!< held plant input
  const typename Controller::Output& command;        //!< the law's output
  const typename Controller::Diagnostics& controller_diagnostics;
  Status controller_status;
  const typename Actuation::Output& actuation;       //!< the actuation stage's output
  const typename Actuation::Diagnostics& actuation_diagnostics;
  Status actuation_status;
  bool final;                                        //!< true for the extra call at t_end
};

//! Runs the loop of the header comment from x (state at options.t0) to options.t_end; x holds
//! the final state on return. Returns the integrator's step count (RK4 sub-steps, or CVODE's
//! internal steps). Throws SimError on invalid options or an integrator failure.
template <class Plant, class Sensors, class Controller, class ToActuation, class Actuation, class ToPlant,
          class Observer>
long closed_loop(const Plant& plant, typename Plant::State& x, const SampledDataOptions& options,
                 const IntegratorChoice& integrator_choice, Sensors&& sensors, Controller& controller,
                 ToActuation&& to_actuation, Actuation& actuation, ToPlant&& to_plant, Observer&& observer) {
  ADCS_ASSERT_PLANT(Plant);
  ADCS_ASSERT_COMPONENT(Controller);
  ADCS_ASSERT_COMPONENT(Actuation);
  using State = typename Plant::State;
  using Input = typename Plant::Input;
  typename Controller::Output cmd{};
  typename Controller::Diagnostics cdiag{};
  typename Actuation::Output act{};
  typename Actuation::Diagnostics adiag{};
  Status cs = Status::ok, as = Status::ok;
  auto control = [&](double t, const State& xs, Input& u) {
    cs = controller.step(sense(sensors, t, xs, std::as_const(u)), cmd, &cdiag);
    as = actuation.step(to_actuation(t, xs, std::as_const(cmd)), act, &adiag);
    to_plant(t, xs, std::as_const(act), u);
  };
  auto observe = [&](double t, const State& xs, const Input& u) {
    const bool final = t == options.t_end;
    observer(LoopSample<Plant, Controller, Actuation>{t, xs, u, cmd, cdiag, cs, act, adiag, as, final});
  };
  long steps = 0;
  with_integrator(plant, integrator_choice, [&](auto& integrator) {
    run_sampled_data(plant, integrator, x, options, control, observe);
    steps = integrator.steps();
  });
  return steps;
}

//! The identity actuation stage: the law's output goes to the plant as it is (a torque-input
//! plant, or a law that commands its actuators itself, like seed 001's).
template <class Signal>
struct PassThrough {
  struct Params {};
  using Input = Signal;
  using Output = Signal;
  struct Diagnostics {};
  explicit PassThrough(const Params& = {}) noexcept {}
  Status status() const noexcept { return Status::ok; }
  void reset() noexcept {}
  double period_s() const noexcept { return 0.0; }
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* = nullptr) const noexcept {
    out = in;
    return Status::ok;
  }
};

}  // namespace adcs::sim
