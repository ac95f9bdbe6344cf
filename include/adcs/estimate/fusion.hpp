#pragma once
// Fusion of the 27-state ESKF (Algorithm 1) with the per-axis saturated-accelerometer filters
// (Algorithm 2), seed 004 Algorithm 3 (spec §B.6, seed 004 eqs. (35)-(43)), for axis j:
//
//   Γ (3 x 27) selects r_j, ṙ_j, F_Dsc,j (indices 9+j, 12+j, 15+j), Γ⁺ = Γᵀ (orthonormal rows)
//   X̂_1 = Γ X̂¹, P_1 = Γ P¹ Γᵀ;  X̂_o = Λ1 X̂_1 + Λ2 X̂_2 = [r̂ (Alg. 1); ṙ̂ (Alg. 1); f̂ (Alg. 2)]  seed 004 eqs. (35)-(38)
//   P_o = Λ1 P_1 Λ1 + Λ2 P_2 Λ2 (default [D], block-diagonal, PSD) or the literal Λ1 P_1 + Λ2 P_2
//         made symmetric and PSD (option)                                                  seed 004 eq. (39)
//   X̂¹ ← (I − ΓᵀΓ) X̂¹ + Γ⁺ X̂_o,  P¹ ← (I − ΓᵀΓ) P¹ (I − ΓᵀΓ)ᵀ + Γ⁺ P_o Γ⁺ᵀ                seed 004 eqs. (40)-(41)
//   X̂_2 ← X̂_o,  P_2 ← P_o                                                                seed 004 eqs. (42)-(43)
//
// seed 004 eq. (41) as printed zeroes the cross-covariance between the three fused states and the other 24;
// kept. The selection is applied by index, in place (exactly Γ⁺ = Γᵀ; tests compare with the
// matrix form).
#include <type_traits>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/estimate/drag_free_eskf.hpp"
#include "adcs/estimate/extended_state_covariance.hpp"
#include "adcs/estimate/saturated_esf.hpp"
#include "adcs/plant/drag_free.hpp"

namespace adcs {

enum class FusedCovariance {
  block_diagonal,  //!< Λ1 P_1 Λ1 + Λ2 P_2 Λ2 (spec §B.6 default [D])
  literal,         //!< Λ1 P_1 + Λ2 P_2, then symmetrised and clipped PSD (option)
};

//! The Γ of axis j (spec §B.6), for tests and for users who want the matrix form.
inline Mat<3, 27> fusion_selector(int axis) noexcept {
  Mat<3, 27> G = Mat<3, 27>::Zero();
  G(0, DragFreeIndex::r + axis) = 1.0;
  G(1, DragFreeIndex::r_dot + axis) = 1.0;
  G(2, DragFreeIndex::F_Dsc + axis) = 1.0;
  return G;
}

//! Algorithm 3 for one axis: both filters leave with the fused estimate. non_finite_input
//! (nothing changed) if either filter holds a non-finite estimate, out_of_range (nothing changed)
//! when Algorithm 1's fused covariance would exceed double's range, invalid_parameter (nothing
//! changed) for a bad axis or a refused filter (status() != ok: it has no valid estimate to give
//! or to receive).
//! A template only so that including this header instantiates nothing (see detail::DragFreeEskf);
//! Alg1 is DragFreeEskfT<S> (or, in double, DragFreeEskfJoseph) and Alg2 SaturatedEsfT<S>, both in
//! the scalar S (issue 19: Algorithm 3 in float too).
template <class Alg1 = DragFreeEskf, class Alg2 = SaturatedEsf>
[[nodiscard]] Status fuse_axis(Alg1& alg1, Alg2& alg2, int axis,
                               FusedCovariance mode = FusedCovariance::block_diagonal) noexcept {
  using S = typename Alg2::Scalar;
  static_assert((std::is_same_v<Alg1, DragFreeEskfT<S>> ||
                 (std::is_same_v<S, double> && std::is_same_v<Alg1, DragFreeEskfJoseph>)) &&
                    std::is_same_v<Alg2, SaturatedEsfT<S>>,
                "fuse_axis: Algorithm 3 fuses the drag-free ESKF with a saturated-accelerometer filter "
                "of the same scalar");
  using Vec3s = Vec<3, S>;
  using Mat3s = Mat<3, 3, S>;
  if (axis < 0 || axis > 2 || alg1.status() != Status::ok || alg2.status() != Status::ok)
    return Status::invalid_parameter;
  const std::array<int, 3> idx{DragFreeIndex::r + axis, DragFreeIndex::r_dot + axis, DragFreeIndex::F_Dsc + axis};
  const Vec<27, S>& x1 = alg1.state();
  const Vec3s X1(x1(idx[0]), x1(idx[1]), x1(idx[2]));        // seed 004 eq. (35)
  const Mat3s P1s = alg1.template covariance_of<3>(idx);     // seed 004 eq. (36)
  const Vec3s& X2 = alg2.state();
  const Mat3s& P2 = alg2.covariance();
  const Vec3s Xo(X1(0), X1(1), X2(2));                       // seed 004 eqs. (37)-(38)
  Mat3s Po;
  if (mode == FusedCovariance::block_diagonal) {
    Po.setZero();
    Po.template topLeftCorner<2, 2>() = P1s.template topLeftCorner<2, 2>();
    Po(2, 2) = P2(2, 2);
  } else {
    Po << P1s.row(0), P1s.row(1), P2.row(2);                  // literal (39): not symmetric
    keep_psd<3, S>(Po);
  }
  if (!all_finite(Xo) || !all_finite(Po) || !all_finite(x1) || !all_finite(P1s)) return Status::non_finite_input;
  const Status s1 = alg1.template replace_substate<3>(idx, Xo, Po);  // seed 004 eqs. (40)-(41)
  if (s1 != Status::ok) return s1;  // the U-D filter: out_of_range when the fused P is beyond double's range
  return alg2.set_estimate(Xo, Po);                          // seed 004 eqs. (42)-(43)
}

}  // namespace adcs
