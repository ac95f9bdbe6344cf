#pragma once
// Algorithm 1 (ESKF) for the 27-state drag-free model, run as the two uncoupled blocks the model
// has (spec §B.2.2 index map): the attitude chain φ_sc, φ̇_sc, T_Dsc, φ_rel, φ̇_rel, T_Dtm
// (18 states, outputs φ_sc and φ_rel; seed 004 eq. (3) couples φ_rel to the spacecraft's torques) and the
// translation r, ṙ, F_Dsc (9 states, output r_rel). Nothing in A_d, B_d S B_dᵀ, B_e, C_d, R or
// P_0 = 0.01 I couples them, so this is Algorithm 1 exactly (see PartitionedEskf) at about a third
// of the work of the 27-state matrices. Construction rejects parameters that do couple them.
#include "adcs/core/component.hpp"
#include "adcs/estimate/partitioned_eskf.hpp"
#include "adcs/plant/drag_free.hpp"

namespace adcs {

using DragFreeEskfBase = PartitionedEskf<18, 9, kDragFreeInputs, kDragFreeInputs, 6, 3>;

//! The attitude block: state indices 0-8 and 18-26, outputs φ_sc (0-2) and φ_rel (6-8).
inline DragFreeEskfBase::Partition drag_free_attitude_partition() noexcept {
  DragFreeEskfBase::Partition part;
  for (int i = 0; i < 9; ++i) {
    part.states[i] = DragFreeIndex::phi_sc + i;
    part.states[9 + i] = DragFreeIndex::phi_rel + i;
  }
  for (int i = 0; i < 3; ++i) {
    part.outputs[i] = i;
    part.outputs[3 + i] = 6 + i;
  }
  return part;
}

namespace detail {
//! DragFreeEskf itself, a template over its base only so that including this header instantiates
//! nothing: g++ instantiates every template that a non-template inline function calls, used or
//! not, and the two Eskf blocks' constructors (their parameter checks) cost ~18 CPU-s in every
//! translation unit that included this header (docs/DECISIONS.md, "Unity batches").
template <class Base>
class DragFreeEskf : public Base {
 public:
  explicit DragFreeEskf(const typename Base::Params& p) noexcept : Base(p, drag_free_attitude_partition()) {}

  //! ok, or invalid_parameter: an unset (NaN) or invalid matrix, or parameters that couple the
  //! attitude and translation blocks (PartitionedEskf::status). A refused filter answers
  //! invalid_parameter from predict() and update() and leaves its estimate untouched;
  //! fuse_axis() refuses it too.
  Status status() const noexcept { return Base::status(); }
};
}  // namespace detail

//! Parameters: EskfParams<27, 9, 9, 9> (the model matrices and R have no default; X̂_0, P_0 are
//! spec §B.4's), usually from drag_free_discretize() as the dragfree-* scenarios build them.
using DragFreeEskf = detail::DragFreeEskf<DragFreeEskfBase>;

ADCS_ASSERT_COMPONENT(DragFreeEskf);

}  // namespace adcs
