#pragma once
// The drag-free satellite as a plant of the one plant shape (core/plant.hpp): the continuous
// extended model of seed 004 eq. (6), Ẋ = A X + B u (27 states in DragFreeIndex order; the input
// u = [T_Csc; F_Csc; T_Ctm] + w held over a period; the disturbances f are states, constant
// between samples, so B_e ḟ = 0 inside a period). Integrated over one period with u held it is
// the exact ZOH model drag_free_discretize() gives (tests/plant/test_plant_concept.cpp checks it
// against A_d X + B_d u), which is what the dragfree-* scenarios step with their per-sample
// noise and disturbance increments.
#include "adcs/core/plant.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/plant/drag_free.hpp"

namespace adcs {

class DragFreePlant {
 public:
  static constexpr int kStateSize = kDragFreeStates;
  static constexpr int kInputSize = kDragFreeInputs;
  using State = Vec<kStateSize>;
  using Input = Vec<kInputSize>;
  using Params = DragFreeParams;

  explicit DragFreePlant(const Params& p) noexcept
      : p_(p), status_(valid(p) ? Status::ok : Status::invalid_parameter) {
    if (status_ == Status::ok) m_ = drag_free_continuous(p_);
  }
  //! ok, or invalid_parameter (valid(DragFreeParams)); a refused plant's derivative is 0.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  const DragFreeContinuous& model() const noexcept { return m_; }

  void derivative(double /*t*/, const State& x, const Input& u, State& xdot) const noexcept {
    if (status_ != Status::ok) {
      xdot.setZero();
      return;
    }
    xdot.noalias() = m_.A * x;  // seed 004 eq. (6)
    xdot.noalias() += m_.B * u;
  }

 private:
  Params p_;
  Status status_;
  DragFreeContinuous m_{};
};

ADCS_ASSERT_PLANT(DragFreePlant);

}  // namespace adcs
