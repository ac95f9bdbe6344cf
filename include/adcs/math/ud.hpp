#pragma once
// U-D covariance factors, P = U D Uᵀ with U unit upper triangular and D diagonal ≥ 0 (Bierman,
// "Factorization Methods for Discrete Sequential Estimation", 1977; Thornton 1976). A covariance
// kept as (U, D) is positive semidefinite by construction: every operation below produces D ≥ 0
// from sums of squares with non-negative weights, so no PSD test and no projection is needed.
//
//   ud_factorize        P → (U, D)                  N³/6 multiply-adds, refuses P ∉ PSD cone
//   ud_covariance       (U, D) → P, and one entry P_ij
//   mwgs_ud             W diag(w) Wᵀ → (U, D)        Thornton's modified weighted Gram-Schmidt
//   bierman_update      one scalar measurement       Bierman's update, O(N²), gain out
#include <array>
#include <cmath>
#include <limits>

#include "adcs/core/types.hpp"

namespace adcs {

// Every kernel takes the scalar S (issue 19; double by default, float for a single-precision FPU):
// the operations are the same, and D >= 0 holds whatever the rounding in either precision.

//! U-D factors of an N x N covariance.
template <int N, class S = double>
struct UdFactors {
  Mat<N, N, S> U;  //!< unit upper triangular
  Vec<N, S> D;     //!< diagonal, >= 0
  //! P = 0 (U = I, D = 0). Not the default constructor: a step's candidate factors are written
  //! whole before use, and initialising them cost ~3% of the drag-free step (memset).
  static UdFactors zero() noexcept {
    UdFactors f;
    f.U.setIdentity();
    f.D.setZero();
    return f;
  }
};

//! P = U D Uᵀ (formed; N³/6 multiply-adds: not for a step path).
template <int N, class S>
Mat<N, N, S> ud_covariance(const UdFactors<N, S>& f) noexcept {
  Mat<N, N, S> P;
  for (int j = 0; j < N; ++j)
    for (int i = 0; i <= j; ++i) {
      S s = S(0);
      for (int k = j; k < N; ++k) s += f.U(i, k) * f.D(k) * f.U(j, k);
      P(i, j) = s;
      P(j, i) = s;
    }
  return P;
}

//! P_ij = Σ_{k ≥ max(i, j)} U_ik D_k U_jk.
template <int N, class S>
S ud_covariance_entry(const UdFactors<N, S>& f, int i, int j) noexcept {
  S s = S(0);
  for (int k = i > j ? i : j; k < N; ++k) s += f.U(i, k) * f.D(k) * f.U(j, k);
  return s;
}

//! P → (U, D), columns from the last (upper U-D, Bierman 1977 §III.2). A pivot within
//! 64 N ε of its diagonal entry is rounding and is taken as 0 (its column of U zeroed), so a
//! semidefinite P (a state with zero variance, as the fusion of seed 004 eq. (41) leaves) is
//! factored exactly. Returns false, out untouched, when P is not finite or a pivot is negative
//! beyond that tolerance (P not PSD: there is no U-D factor to give).
template <int N, class S>
bool ud_factorize(const Mat<N, N, S>& P, UdFactors<N, S>& out) noexcept {
  if (!all_finite(P)) return false;
  // 64 N ε of the scalar (double: 64 N · 2.22e-16, as before issue 19; float: 64 N · 1.19e-7).
  constexpr S kTol = S(64) * S(N) * std::numeric_limits<S>::epsilon();
  UdFactors<N, S> f = UdFactors<N, S>::zero();
  for (int j = N - 1; j >= 0; --j) {
    S d = P(j, j);
    for (int k = j + 1; k < N; ++k) d -= f.U(j, k) * f.U(j, k) * f.D(k);
    const S tol = kTol * std::abs(P(j, j));
    if (d < -tol || !(P(j, j) >= S(0))) return false;
    if (d <= tol) {  // zero variance left for state j: nothing to regress on it
      f.D(j) = S(0);
      for (int i = 0; i < j; ++i) f.U(i, j) = S(0);
      continue;
    }
    f.D(j) = d;
    for (int i = 0; i < j; ++i) {
      S s = P(i, j);
      for (int k = j + 1; k < N; ++k) s -= f.U(i, k) * f.D(k) * f.U(j, k);
      f.U(i, j) = s / d;
    }
  }
  out = f;
  return true;
}

//! Thornton's modified weighted Gram-Schmidt: the U-D factors of W diag(w) Wᵀ for an N x M
//! matrix W and weights w ≥ 0 (Bierman 1977 §VI.3; Grewal & Andrews, Kalman Filtering, §6.6.2).
//! Rows are orthogonalised from the last, each against all the rows above it at once (the modified
//! form, stable where the classical one loses orthogonality): for row j, u = W_{0:j} (w ∘ W_j)ᵀ /
//! D_j and W_{0:j} −= u W_j, a matrix-vector product and a rank-one update on contiguous columns.
//! W is overwritten. D_j = Σ_k w_k W_jk² ≥ 0, so the result is PSD whatever the rounding; a row
//! with zero weighted norm gives D_j = 0 and U(:, j) = e_j. ~N² M multiply-adds for a dense W.
//!
//! Structure: only columns [first[i], m) of row i may be nonzero (m ≤ M: the columns in use).
//! Removing row j from the rows above keeps them zero before min(first[i], first[j]), so both
//! products run over columns [first[j], m) only: for A_d U with A_d upper triangular outside a
//! small leading block (the drag-free attitude chain in its U-D order) that is about half of the
//! dense work. The skipped terms are exact zeros.
//! Only the first n rows take part: columns 0..n−1 of out.U and D(0..n−1) are written, the
//! others are left to the caller (EskfUd's time update writes them itself: setting all of an
//! 18 x 18 U to the identity first was a 2.6 kB memset per step).
template <int N, int M, class S>
void mwgs_ud(Mat<N, M, S>& W, const Eigen::Matrix<S, 1, M>& w, std::array<int, N> first, int n, int m,
             UdFactors<N, S>& out) noexcept {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < N; ++i) out.U(i, j) = i == j ? S(1) : S(0);
  S c[M];
  S u[N];
  for (int j = n - 1; j >= 0; --j) {
    const int a = first[j];
    S d = S(0);
    for (int k = a; k < m; ++k) {
      c[k] = W(j, k) * w(k);  // w ∘ W_j
      d += W(j, k) * c[k];
    }
    out.D(j) = d;
    if (!(d > S(0)) || j == 0) continue;  // W_j is zero in the weighted norm: nothing to remove
    for (int i = 0; i < j; ++i) u[i] = S(0);
    for (int k = a; k < m; ++k) {  // u = W_{0:j} c / d, column by column (contiguous)
      const S* col = W.col(k).data();
      for (int i = 0; i < j; ++i) u[i] += col[i] * c[k];
    }
    for (int i = 0; i < j; ++i) {
      u[i] /= d;
      out.U(i, j) = u[i];
      first[i] = first[i] < a ? first[i] : a;
    }
    for (int k = a; k < m; ++k) {  // W_{0:j} −= u W_j
      S* col = W.col(k).data();
      const S wjk = col[j];
      for (int i = 0; i < j; ++i) col[i] -= u[i] * wjk;
    }
  }
}
//! Dense W: every column of every row in use.
template <int N, int M, class S>
void mwgs_ud(Mat<N, M, S>& W, const Eigen::Matrix<S, 1, M>& w, UdFactors<N, S>& out) noexcept {
  std::array<int, N> first{};
  mwgs_ud<N, M, S>(W, w, first, N, M, out);
}

namespace detail {
// The row loops of the two updates below read each entry once into a local: written as
// `a[i] -= v * u[i]; u[i] += bv * a[i]` the compiler must reload u[i] after the store to a[i]
// (they might overlap), one more Cortex-M7 instruction per entry. Same operations, same order:
// the same bits.
template <class S>
inline void agee_turner_rows(S* u, S* a, S v, S bv, int n) noexcept {
  for (int i = 0; i < n; ++i) {
    const S ui = u[i];
    const S ai = a[i] - v * ui;
    a[i] = ai;
    u[i] = ui + bv * ai;
  }
}
template <class S>
inline void bierman_rows(S* u, S* b, S p, S v, int n) noexcept {
  for (int i = 0; i < n; ++i) {
    const S uij = u[i];
    const S bi = b[i];
    u[i] = uij + bi * p;
    b[i] = bi + uij * v;
  }
}
// The same, reading column j from another factor's (bierman_update out of place). A separate
// loop: with u_in == u the host compilers' run-time overlap test fails and the vectorised loop is
// skipped (+4,300 x86 instructions per drag-free sample, measured), so the in-place update keeps
// its two-pointer loop.
template <class S>
inline void bierman_rows(const S* u_in, S* u, S* b, S p, S v, int n) noexcept {
  for (int i = 0; i < n; ++i) {
    const S uij = u_in[i];
    const S bi = b[i];
    u[i] = uij + bi * p;
    b[i] = bi + uij * v;
  }
}
}  // namespace detail

//! Agee–Turner rank-one modification (Bierman 1977 §V.4; Thornton 1976): (U, D) ← the U-D factors
//! of U D Uᵀ + c a aᵀ for c ≥ 0, in place; `a` is used as scratch. Columns from the last:
//!   d̄_j = d_j + c_j a_j²,  b_j = c_j / d̄_j,  c_{j−1} = d_j b_j,  a_{0:j} −= a_j U(0:j, j),
//!   U(0:j, j) += b_j a_j a_{0:j}
//! With c ≥ 0 every d̄_j ≥ d_j ≥ 0 and c_j ≥ 0 (no subtraction of variances: the stable case).
//! Columns where a_j = 0 change nothing and are skipped, so a vector with few nonzeros (a
//! selector, the rows above a state) costs only those columns.
template <int N, class S>
void agee_turner_update(UdFactors<N, S>& f, identity_t<S> c, Vec<N, S>& a) noexcept {
  S* av = a.data();
  for (int j = N - 1; j > 0 && c > S(0); --j) {
    const S v = av[j];
    if (v == S(0)) continue;  // nothing of this column: d_j and c unchanged
    const S d_new = f.D(j) + c * v * v;
    const S b = c / d_new;
    c = f.D(j) * b;
    f.D(j) = d_new;
    detail::agee_turner_rows<S>(f.U.col(j).data(), av, v, b * v, j);
  }
  if (c > S(0)) f.D(0) += c * av[0] * av[0];
}

//! Bierman's scalar measurement update (Bierman 1977 §V.3) of (U, D) for z = h x + v, var(v) = r
//! > 0: updates the factors in place and writes the Kalman gain k (x⁺ = x + k (z − h x)). f = Uᵀhᵀ
//! is given from `first` on (U upper triangular: first = the lowest index where h is nonzero; f is
//! zero before it, and those entries are not read), which skips the columns j < first, where the
//! update changes nothing.
//! α grows from r > 0, so every D_j stays ≥ 0. Returns α = h P hᵀ + r, the innovation variance.
//! Out of place: the factors `in` updated into `f` (the same bits as updating a copy in place, and
//! no copy: EskfUd's first measurement of a sample writes its candidate this way). Only U's
//! entries above the diagonal and D are written: f's diagonal and the entries below it must be
//! those of a unit upper triangular U already, as in every factor these kernels write.
template <int N, class S>
S bierman_update(const UdFactors<N, S>& in, UdFactors<N, S>& f, const Vec<N, S>& fvec, identity_t<S> r, int first,
                 Vec<N, S>& k) noexcept {
  if (&in != &f)
    for (int j = 0; j < first; ++j) {  // the columns this measurement leaves unchanged
      for (int i = 0; i < j; ++i) f.U(i, j) = in.U(i, j);
      f.D(j) = in.D(j);
    }
  S b[N];  // b[j] is written at column j before it is read; only those before `first` start at 0
  for (int i = 0; i < first; ++i) b[i] = S(0);
  S alpha = r;
  for (int j = first; j < N; ++j) {
    const S v = in.D(j) * fvec(j);
    const S alpha_next = alpha + fvec(j) * v;
    const S p = -fvec(j) / alpha;
    f.D(j) = in.D(j) * (alpha / alpha_next);
    if (&in == &f)
      detail::bierman_rows<S>(f.U.col(j).data(), b, p, v, j);
    else
      detail::bierman_rows<S>(in.U.col(j).data(), f.U.col(j).data(), b, p, v, j);
    b[j] = v;
    alpha = alpha_next;
  }
  for (int i = 0; i < N; ++i) k(i) = b[i] / alpha;
  return alpha;
}
//! In place.
template <int N, class S>
S bierman_update(UdFactors<N, S>& f, const Vec<N, S>& fvec, identity_t<S> r, int first, Vec<N, S>& k) noexcept {
  return bierman_update<N, S>(f, f, fvec, r, first, k);
}

}  // namespace adcs
