#pragma once
// d/dt f(x(t)) by central differences along the flow direction xdot: the conservation checks of
// every plant test (momentum, energy) evaluate it on the right-hand side itself.
template <class State, class F>
auto directional(const F& f, const State& x, const State& xdot, double h) {
  using R = decltype(f(x));  // evaluate: an Eigen expression would dangle on return
  const R hi = f(State(x + h * xdot));
  const R lo = f(State(x - h * xdot));
  return R((hi - lo) / (2.0 * h));
}
