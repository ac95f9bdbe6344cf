#pragma once
// The nonzeros of a fixed R x N matrix X, listed once row by row (compressed rows), to form
// Y Xᵀ for an N-column Y: (Y Xᵀ)(:, i) = Σ_j X(i, j) Y(:, j), each output column accumulated
// in registers from contiguous input columns (column-major) and stored once. Seed 004's
// filters form A P Aᵀ, A U and P Cᵀ this way (the drag-free A_d has 162 of 729 nonzeros, C_d 9
// of 243). S is the scalar (issue 19; double by default).
#include <array>
#include <cstdint>

#include "adcs/core/types.hpp"

namespace adcs {

template <int R, int N, class S = double>
struct SparseRows {
  std::array<std::uint16_t, R * N> col{};
  std::array<S, R * N> val{};
  std::array<int, R + 1> start{};  //!< row i's entries are [start[i], start[i+1])
  int count = 0;

  void assign(const Mat<R, N, S>& X) noexcept {
    count = 0;
    for (int i = 0; i < R; ++i) {
      start[i] = count;
      for (int j = 0; j < N; ++j)
        if (X(i, j) != S(0)) {
          col[count] = static_cast<std::uint16_t>(j);
          val[count] = X(i, j);
          ++count;
        }
    }
    start[R] = count;
  }

  //! Y Xᵀ.
  template <int NR>
  Mat<NR, R, S> mul_by_transpose(const Mat<NR, N, S>& Y) const noexcept {
    Mat<NR, R, S> out;
    for (int i = 0; i < R; ++i) {
      Vec<NR, S> acc = Vec<NR, S>::Zero();
      for (int k = start[i]; k < start[i + 1]; ++k) acc += val[k] * Y.col(col[k]);
      out.col(i) = acc;
    }
    return out;
  }

  //! out += X v, each row's sum formed first over its nonzeros in column order, then added. That is
  //! the order of Eigen's matrix-vector kernel: for the drag-free blocks' B_d and B_e (18 x 9, 9 x 9)
  //! the result is out.noalias() += X * v bit for bit, measured with g++ and clang (issue 20); in
  //! general the two agree to rounding.
  void add_product(const Vec<N, S>& v, Vec<R, S>& out) const noexcept {
    for (int i = 0; i < R; ++i) out(i) += row_dot(i, v);
  }
  //! X(i, :) v.
  S row_dot(int i, const Vec<N, S>& v) const noexcept {
    S s = S(0);
    for (int k = start[i]; k < start[i + 1]; ++k) s += val[k] * v(col[k]);
    return s;
  }

  //! The lowest column index with a nonzero in row i (N for an empty row).
  int first_col(int i) const noexcept {
    int first = N;
    for (int k = start[i]; k < start[i + 1]; ++k) first = col[k] < first ? col[k] : first;
    return first;
  }
};

}  // namespace adcs
