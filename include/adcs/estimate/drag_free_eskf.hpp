#pragma once
// Algorithm 1 (ESKF) for the 27-state drag-free model, run as the two uncoupled blocks the model
// has (spec §B.2.2 index map): the attitude chain φ_sc, φ̇_sc, T_Dsc, φ_rel, φ̇_rel, T_Dtm
// (18 states, outputs φ_sc and φ_rel; seed 004 eq. (3) couples φ_rel to the spacecraft's torques) and the
// translation r, ṙ, F_Dsc (9 states, output r_rel). Nothing in A_d, B_d S B_dᵀ, B_e, C_d, R or
// P_0 = 0.01 I couples them, so this is Algorithm 1 exactly (see PartitionedFilter) at about a
// third of the work of the 27-state matrices. Construction rejects parameters that do couple them.
//
// DragFreeEskf keeps each block's covariance as U-D factors (EskfUd, issue 20): PSD by
// construction, no PSD test or eigen projection on the step. DragFreeEskfJoseph is the same
// filter in the Joseph form (Eskf), the reference the tests compare against. Within a block
// nothing decouples further: I_sc, K_rot and K_trans couple the axes (seed 004 Table 2), and the
// attitude chain drives the relative one (seed 004 eq. (3)).
#include "adcs/core/component.hpp"
#include "adcs/estimate/eskf_ud.hpp"
#include "adcs/estimate/partitioned_eskf.hpp"
#include "adcs/plant/drag_free.hpp"

namespace adcs {

//! The noise columns each U-D block can hold: the attitude block has B_e's T_Dsc and T_Dtm
//! columns and B_d's T_Csc and T_Ctm ones (12; with spec §B.8's q = 0 on T_Dtm, 9 are used), the
//! translation block F_Dsc's and F_Csc's (6). Parameters that need more couple the blocks and are
//! refused anyway (PartitionedFilter::status).
inline constexpr int kDragFreeAttitudeNoiseColumns = 12, kDragFreeTranslationNoiseColumns = 6;

template <class S>
using DragFreeEskfBaseT =
    PartitionedFilter<EskfUd<18, kDragFreeInputs, kDragFreeInputs, 6, kDragFreeAttitudeNoiseColumns, S>,
                      EskfUd<9, kDragFreeInputs, kDragFreeInputs, 3, kDragFreeTranslationNoiseColumns, S>>;
using DragFreeEskfBase = DragFreeEskfBaseT<double>;
using DragFreeEskfJosephBase = PartitionedEskf<18, 9, kDragFreeInputs, kDragFreeInputs, 6, 3>;

namespace detail {
//! The attitude block as two 9-state chains (φ, φ̇, T_D of the spacecraft or of the relative
//! motion) and their two 3-output groups, each in the given order.
inline FilterPartition<18, 6> attitude_partition(int first_chain, int second_chain, int first_outputs,
                                                 int second_outputs) noexcept {
  FilterPartition<18, 6> part;
  for (int i = 0; i < 9; ++i) {
    part.states[i] = first_chain + i;
    part.states[9 + i] = second_chain + i;
  }
  for (int i = 0; i < 3; ++i) {
    part.outputs[i] = first_outputs + i;
    part.outputs[3 + i] = second_outputs + i;
  }
  return part;
}
}  // namespace detail

//! The attitude block: state indices 0-8 and 18-26, outputs φ_sc (0-2) and φ_rel (6-8).
inline FilterPartition<18, 6> drag_free_attitude_partition() noexcept {
  return detail::attitude_partition(DragFreeIndex::phi_sc, DragFreeIndex::phi_rel, 0, 6);
}

//! The attitude block in the U-D filter's order: φ_rel, φ̇_rel, T_Dtm, φ_sc, φ̇_sc, T_Dsc. Each
//! state comes before the states its row of A_d depends on (seed 004 eqs. (1), (3): φ_sc on φ̇_sc
//! and T_Dsc, φ_rel and φ̇_rel on each other, T_Dsc and T_Dtm), so A_d is upper triangular but for
//! the 6 x 6 (φ_rel, φ̇_rel) oscillator and Thornton's re-factoring skips the zeros below the
//! diagonal (mwgs_ud). Outputs φ_rel (6-8), then φ_sc (0-2).
inline FilterPartition<18, 6> drag_free_attitude_partition_ud() noexcept {
  return detail::attitude_partition(DragFreeIndex::phi_rel, DragFreeIndex::phi_sc, 6, 0);
}

namespace detail {
//! DragFreeEskf itself, a template over its base only so that including this header instantiates
//! nothing: g++ instantiates every template that a non-template inline function calls, used or
//! not, and the two Eskf blocks' constructors (their parameter checks) cost ~18 CPU-s in every
//! translation unit that included this header (docs/DECISIONS.md, "Unity batches").
template <class Base, FilterPartition<18, 6> (*kPartition)()>
class DragFreeEskf : public Base {
 public:
  explicit DragFreeEskf(const typename Base::Params& p) noexcept : Base(p, kPartition()) {}

  //! ok, or invalid_parameter: an unset (NaN) or invalid matrix, or parameters that couple the
  //! attitude and translation blocks (PartitionedEskf::status). A refused filter answers
  //! invalid_parameter from predict() and update() and leaves its estimate untouched;
  //! fuse_axis() refuses it too.
  Status status() const noexcept { return Base::status(); }
};
}  // namespace detail

//! Parameters: EskfParams<27, 9, 9, 9> (the model matrices and R have no default; X̂_0, P_0 are
//! spec §B.4's), usually from drag_free_discretize() as the dragfree-* scenarios build them.
//! DragFreeEskfT<float> is the same filter in float (issue 19), its parameters the double ones
//! rounded once (EskfParams::cast<float>()); what its estimates keep of seed 004's precision is
//! measured in tests/estimate/test_drag_free_eskf_float.cpp.
template <class S>
using DragFreeEskfT = detail::DragFreeEskf<DragFreeEskfBaseT<S>, drag_free_attitude_partition_ud>;
using DragFreeEskf = DragFreeEskfT<double>;
//! The same filter in the Joseph form: the reference of the tests and of BM_DragFreeEskfJoseph_Step.
using DragFreeEskfJoseph = detail::DragFreeEskf<DragFreeEskfJosephBase, drag_free_attitude_partition>;

ADCS_ASSERT_COMPONENT(DragFreeEskf);
ADCS_ASSERT_COMPONENT(DragFreeEskfT<float>);
ADCS_ASSERT_COMPONENT(DragFreeEskfJoseph);

}  // namespace adcs
