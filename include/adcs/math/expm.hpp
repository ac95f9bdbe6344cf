#pragma once
// Matrix exponential of a fixed-size matrix and the zero-order-hold (ZOH) discretisation built on
// it. Used at set-up (model discretisation), not in a step().
//
// Method: scaling and squaring with diagonal Padé approximants, Algorithm 2.3 of
//   N. J. Higham, "The scaling and squaring method for the matrix exponential revisited",
//   SIAM J. Matrix Anal. Appl. 26(4):1179-1193, 2005.
// With ||A||_1 <= theta_m for m in {3, 5, 7, 9} the degree-m approximant r_m(A) is used
// unscaled; otherwise s = max(0, ceil(log2(||A||_1 / theta_13))), X = r_13(2^-s A) and
// exp(A) = X^(2^s). theta_m (Table 2.3 of the paper) bound the backward error of r_m by the unit
// roundoff 2^-53. r_m = q_m(A)^-1 p_m(A) with p_m = V + U, q_m = V - U (U odd, V even terms).
//
// The denominator solve is an LU factorisation with partial pivoting written out on the
// fixed-size matrix (no Eigen::PartialPivLU: for n > 16 Eigen switches to its blocked LU, whose
// dynamic-size GEMM/TRSM take a heap buffer where Eigen has no alloca, as on arm-none-eabi). One
// refinement: when the row on the diagonal has no entry right of the diagonal (and a nonzero
// one on it) it is taken as the pivot. That step leaves the trailing matrix unchanged and adds
// only the column's own |q_ik| to |L||U|, so it is as stable as any pivot; and it makes zero rows
// exact: a zero row i of A gives row i of exp(A) = e_i^T bit for bit, so ZOH disturbance and
// input states stay exactly constant (plain partial pivoting can lose this when a scaled gain
// from such a state exceeds ~2, as b_1 = b_0 / 2). Products use Eigen's coefficient-based
// lazyProduct: no blocking buffers, so the stack use is the named workspace only.
//
// Cost: (pi_m + s) N x N products + one LU solve, pi_m = 2, 3, 4, 5, 6 for m = 3, 5, 7, 9, 13.
// Stack (arm-none-eabi -O2): 62 KB in expm<36>, +21 KB in zoh_discretize<27, 9>; ~6 N^2 doubles.
// Accuracy: forward error ~ kappa_exp(A) u with kappa_exp >= ||A||. Measured against a
// long-double reference: <= 2e-15 relative (1-norm) for ||A||_1 <= 20, ~1.6e-13 at 1e3 (as
// Eigen's MatrixFunctions exp()); single entries/scalars reach ~37 |a| eps near |a| ~ 42 (the
// cancellation in q_13 at ||2^-s A|| ~ theta_13, also in Eigen's). Higham 2005 may overscale
// strongly non-normal matrices (large ||A||, small spectrum), costing accuracy only on such
// inputs (Al-Mohy & Higham 2009 fixes that; not implemented).
#include <cmath>
#include <utility>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

namespace detail {

// Padé coefficients b_0..b_m of r_m (Higham 2005, Algorithm 2.3) and the thresholds theta_m for
// IEEE double (Table 2.3).
inline constexpr double kPade3[] = {120.0, 60.0, 12.0, 1.0};
inline constexpr double kPade5[] = {30240.0, 15120.0, 3360.0, 420.0, 30.0, 1.0};
inline constexpr double kPade7[] = {17297280.0, 8648640.0, 1995840.0, 277200.0,
                                    25200.0,    1512.0,    56.0,      1.0};
inline constexpr double kPade9[] = {17643225600.0, 8821612800.0, 2075673600.0, 302702400.0,
                                    30270240.0,    2162160.0,    110880.0,     3960.0,
                                    90.0,          1.0};
inline constexpr double kPade13[] = {64764752532480000.0, 32382376266240000.0, 7771770303897600.0,
                                     1187353796428800.0,  129060195264000.0,   10559470521600.0,
                                     670442572800.0,      33522128640.0,       1323241920.0,
                                     40840800.0,          960960.0,            16380.0,
                                     182.0,               1.0};
inline constexpr double kTheta3 = 1.495585217958292e-2;
inline constexpr double kTheta5 = 2.539398330063230e-1;
inline constexpr double kTheta7 = 9.504178996162932e-1;
inline constexpr double kTheta9 = 2.097847961257068e0;
inline constexpr double kTheta13 = 5.371920351148152e0;

//! X = Q^-1 P in place: Q is overwritten by its LU factors, P by X. Partial pivoting, except
//! that a diagonal row with no entry right of the diagonal is taken as the pivot (see the file
//! comment). Returns singular on an exactly zero pivot or a non-finite X (P then undefined).
template <int N>
Status lu_solve_in_place(Mat<N, N>& Q, Mat<N, N>& P) noexcept {
  for (int k = 0; k < N; ++k) {
    bool singleton = Q(k, k) != 0.0;
    for (int j = k + 1; j < N && singleton; ++j) singleton = Q(k, j) == 0.0;
    int p = k;
    if (!singleton) {
      double best = std::abs(Q(k, k));
      for (int i = k + 1; i < N; ++i) {
        const double v = std::abs(Q(i, k));
        if (v > best) {
          best = v;
          p = i;
        }
      }
      if (!(best > 0.0)) return Status::singular;
      if (p != k) {
        Q.row(k).swap(Q.row(p));
        P.row(k).swap(P.row(p));
      }
    }
    const double pivot = Q(k, k);
    for (int i = k + 1; i < N; ++i) Q(i, k) /= pivot;
    if (singleton) continue;  // row k is zero right of the pivot: no trailing update
    for (int j = k + 1; j < N; ++j) {
      const double u = Q(k, j);
      if (u == 0.0) continue;
      for (int i = k + 1; i < N; ++i) Q(i, j) -= Q(i, k) * u;
    }
  }
  for (int c = 0; c < N; ++c) {
    for (int k = 0; k < N; ++k) {  // L y = P (unit lower)
      const double y = P(k, c);
      if (y == 0.0) continue;
      for (int i = k + 1; i < N; ++i) P(i, c) -= Q(i, k) * y;
    }
    for (int k = N - 1; k >= 0; --k) {  // U x = y
      P(k, c) /= Q(k, k);
      const double x = P(k, c);
      if (x == 0.0) continue;
      for (int i = 0; i < k; ++i) P(i, c) -= Q(i, k) * x;
    }
  }
  return all_finite(P) ? Status::ok : Status::singular;
}

//! Scratch matrices of expm (one object so the stack cost is explicit).
template <int N>
struct ExpmWork {
  Mat<N, N> a, a2, a4, a6, t, u;
};

}  // namespace detail

//! Matrix exponential exp(A) of a fixed-size N x N matrix (A dimensionless, e.g. A_c h), by
//! Padé scaling and squaring (Higham 2005, see the file comment). Returns ok with out = exp(A);
//! non_finite_input if A has a NaN/Inf entry; out_of_range if ||A||_1 overflows or exp(A)
//! overflows (not representable: e.g. a real eigenvalue > ~709); singular if the Padé denominator
//! solve fails (not expected for finite A: q_m is well conditioned for ||A||_1 <= theta_m).
//! out is untouched on every error and may alias A.
template <int N>
[[nodiscard]] Status expm(const Mat<N, N>& A, Mat<N, N>& out) noexcept {
  static_assert(N >= 1 && N <= 64, "fixed-size expm is for 1 <= n <= 64 (stack: ~6 n^2 doubles)");
  using M = Mat<N, N>;
  if (!all_finite(A)) return Status::non_finite_input;
  const double norm1 = A.cwiseAbs().colwise().sum().maxCoeff();
  if (!std::isfinite(norm1)) return Status::out_of_range;

  detail::ExpmWork<N> w;
  int s = 0;
  M* U = nullptr;  // points into w once computed
  M* V = nullptr;
  if (norm1 <= detail::kTheta9) {
    // Lowest degree whose theta_m bounds ||A||_1 (Higham 2005, Algorithm 2.3, lines 1-3).
    const int m = norm1 <= detail::kTheta3   ? 3
                  : norm1 <= detail::kTheta5 ? 5
                  : norm1 <= detail::kTheta7 ? 7
                                             : 9;
    const double* const b = m == 3   ? detail::kPade3
                            : m == 5 ? detail::kPade5
                            : m == 7 ? detail::kPade7
                                     : detail::kPade9;
    // u = sum_{j odd} b_j A^(j-1),  t = sum_{j even} b_j A^j  (A^8 kept in a).
    w.a2.noalias() = A.lazyProduct(A);
    w.u = b[3] * w.a2;
    w.u.diagonal().array() += b[1];
    w.t = b[2] * w.a2;
    w.t.diagonal().array() += b[0];
    if (m >= 5) {
      w.a4.noalias() = w.a2.lazyProduct(w.a2);
      w.u += b[5] * w.a4;
      w.t += b[4] * w.a4;
    }
    if (m >= 7) {
      w.a6.noalias() = w.a4.lazyProduct(w.a2);
      w.u += b[7] * w.a6;
      w.t += b[6] * w.a6;
    }
    if (m >= 9) {
      w.a.noalias() = w.a4.lazyProduct(w.a4);
      w.u += b[9] * w.a;
      w.t += b[8] * w.a;
    }
    w.a.noalias() = A.lazyProduct(w.u);
    U = &w.a;
    V = &w.t;
  } else {
    const double* const b = detail::kPade13;
    int e = 0;
    const double f = std::frexp(norm1 / detail::kTheta13, &e);  // norm1/theta = f 2^e, f in [0.5, 1)
    s = (f == 0.5) ? e - 1 : e;                                 // ceil(log2(norm1/theta13))
    if (s < 0) s = 0;
    w.a = std::ldexp(1.0, -s) * A;  // exact scaling by a power of two
    w.a2.noalias() = w.a.lazyProduct(w.a);
    w.a4.noalias() = w.a2.lazyProduct(w.a2);
    w.a6.noalias() = w.a4.lazyProduct(w.a2);
    // U = A [A6 (b13 A6 + b11 A4 + b9 A2) + b7 A6 + b5 A4 + b3 A2 + b1 I]
    w.t = b[13] * w.a6 + b[11] * w.a4 + b[9] * w.a2;
    w.u.noalias() = w.a6.lazyProduct(w.t);
    w.u += b[7] * w.a6 + b[5] * w.a4 + b[3] * w.a2;
    w.u.diagonal().array() += b[1];
    w.t.noalias() = w.a.lazyProduct(w.u);
    // V = A6 (b12 A6 + b10 A4 + b8 A2) + b6 A6 + b4 A4 + b2 A2 + b0 I
    w.u = b[12] * w.a6 + b[10] * w.a4 + b[8] * w.a2;
    w.a.noalias() = w.a6.lazyProduct(w.u);
    w.a += b[6] * w.a6 + b[4] * w.a4 + b[2] * w.a2;
    w.a.diagonal().array() += b[0];
    U = &w.t;
    V = &w.a;
  }
  // P = V + U into a2; Q = V - U in place of V; X = Q^-1 P into a2.
  w.a2 = *V + *U;
  *V -= *U;
  const Status st = detail::lu_solve_in_place<N>(*V, w.a2);
  if (st != Status::ok) return st;
  M* X = &w.a2;
  M* Y = &w.a4;
  for (int i = 0; i < s; ++i) {
    Y->noalias() = X->lazyProduct(*X);
    std::swap(X, Y);
  }
  if (!all_finite(*X)) return Status::out_of_range;
  out = *X;
  return Status::ok;
}

//! Zero-order-hold discretisation of x_dot = A x + B u with u held over a step of h [s]:
//!   expm([[A, B], [0, 0]] h) = [[A_d, B_d], [0, I]],
//! i.e. A_d = e^(A h), B_d = int_0^h e^(A t) dt B (x_{k+1} = A_d x_k + B_d u_k). A in [1/s], B in
//! [state unit / (input unit s)]. Returns ok; non_finite_input if A, B or h has a NaN/Inf;
//! invalid_parameter if h <= 0; out_of_range if A h, B h or the exponential overflows; singular
//! as expm. A_d and B_d are untouched on every error and may alias A and B.
template <int N, int M>
[[nodiscard]] Status zoh_discretize(const Mat<N, N>& A, const Mat<N, M>& B, double h, Mat<N, N>& A_d,
                                    Mat<N, M>& B_d) noexcept {
  static_assert(N >= 1 && M >= 1, "zoh_discretize needs at least one state and one input");
  if (!all_finite(A) || !all_finite(B) || !std::isfinite(h)) return Status::non_finite_input;
  if (!(h > 0.0)) return Status::invalid_parameter;
  Mat<N + M, N + M> aug = Mat<N + M, N + M>::Zero();
  aug.template topLeftCorner<N, N>() = A * h;
  aug.template topRightCorner<N, M>() = B * h;
  if (!all_finite(aug)) return Status::out_of_range;
  Mat<N + M, N + M> E;
  const Status s = expm<N + M>(aug, E);
  if (s != Status::ok) return s;
  A_d = E.template topLeftCorner<N, N>();
  B_d = E.template topRightCorner<N, M>();
  return Status::ok;
}

}  // namespace adcs
