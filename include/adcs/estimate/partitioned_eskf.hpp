#pragma once
// The ESKF of Algorithm 1 (estimate/eskf.hpp) for a model that splits into two blocks with no
// coupling between them: A_d, Q1, Q2, C_d, R and P_0 block-diagonal after a permutation of the
// states and outputs. Then P stays block-diagonal for ever (prediction, Joseph update and the fusion
// of Algorithm 3 keep it so) and the filter runs as two smaller Eskf blocks, about (N1³ + N2³)/N³
// of the work. The blocks share what couples them in the paper's filter: one θ_k from the traces
// of the whole matrices, θ_k = √((tr Q1¹ + tr Q1²) / (tr A P Aᵀ¹ + tr A P Aᵀ²)), and l = NL in Q1.
// So the estimate is the full filter's up to the order of floating-point sums (tests compare the
// two); a step either succeeds in both blocks or changes nothing.
//
// Block 1 holds the listed states and outputs (in the listed order), block 2 the rest (ascending).
// Construction rejects (invalid_parameter) a partition that is not one, or any nonzero coupling.
#include <array>
#include <cmath>
#include <type_traits>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/estimate/eskf.hpp"
#include "adcs/estimate/extended_state_covariance.hpp"

namespace adcs {

//! The states and outputs of block 1 of a PartitionedFilter (indices into the full vectors).
template <int N1, int NY1>
struct FilterPartition {
  std::array<int, N1> states{};
  std::array<int, NY1> outputs{};
};

//! Two uncoupled blocks of one filter, each an Eskf (Joseph form) or an EskfUd (U-D factors) with
//! the same inputs and channels: both give the block interface propagate(), propagated_trace(),
//! q1_trace(), predict_candidate(), update_candidate(), estimate_candidate(), accept(),
//! covariance_entry() and replace_substate().
template <class Block1T, class Block2T>
class PartitionedFilter {
 public:
  using Block1 = Block1T;
  using Block2 = Block2T;
  static constexpr int N1 = Block1::kStates, N2 = Block2::kStates;
  static constexpr int NY1 = Block1::kOutputs, NY2 = Block2::kOutputs;
  static constexpr int NU = Block1::kInputs, NL = Block1::kChannels;
  static_assert(Block2::kInputs == NU && Block2::kChannels == NL, "PartitionedFilter: the blocks share u and Δf̄");
  static constexpr int N = N1 + N2;
  static constexpr int NY = NY1 + NY2;
  //! The blocks' scalar (issue 19: double, or float for two EskfUd blocks in float).
  using Scalar = typename Block1::Scalar;
  using S = Scalar;
  static_assert(std::is_same_v<typename Block2::Scalar, S>, "PartitionedFilter: the blocks share the scalar");
  using Params = EskfParams<N, NU, NL, NY, S>;
  using Input = EskfInput<NU, NL, NY, S>;
  using Output = EskfOutput<N, S>;
  using Diagnostics = EskfDiagnosticsT<S>;
  using State = Vec<N, S>;
  using Covariance = Mat<N, N, S>;

  using Partition = FilterPartition<N1, NY1>;

  PartitionedFilter(const Params& p, const Partition& part) noexcept
      : status_(split(part)), b1_(sub_params<N1, NY1>(p, s1_, y1_)), b2_(sub_params<N2, NY2>(p, s2_, y2_)) {
    policy_ = p.theta_policy;
    if (status_ == Status::ok && !uncoupled(p)) status_ = Status::invalid_parameter;
    if (status_ == Status::ok && b1_.status() != Status::ok) status_ = b1_.status();
    if (status_ == Status::ok && b2_.status() != Status::ok) status_ = b2_.status();
    const S trP0 = p.P0.trace();
    theta_fixed_ = trP0 > S(0) ? std::sqrt((b1_.q1_trace() + b2_.q1_trace()) / trP0) : S(0);  // θ* of the whole
    assemble_state();
  }

  //! ok, or invalid_parameter: the partition lists repeated or out-of-range indices, a nonzero
  //! entry (NaN included: an unset matrix) couples the blocks, or a block refuses its parameters
  //! (Eskf::status: finite model, q >= 0, S PSD, R SPD, P_0 PSD with tr > 0). A refused filter
  //! answers invalid_parameter from predict() and update() with its estimate untouched.
  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return b1_.period_s(); }

  //! One sample: predict(in.u, in.delta_f_nominal), then update(in.y) (detail::estimator_sample).
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    return detail::estimator_sample(*this, in, out, diag);
  }

  void reset() noexcept {
    b1_.reset();
    b2_.reset();
    theta_ = S(0);
    assemble_state();
  }

  //! Algorithm 1 time update (see Eskf::predict) with the θ of the whole filter.
  [[nodiscard]] Status predict(const Vec<NU, S>& u, const Vec<NL, S>& delta_f_nominal = Vec<NL, S>::Zero()) noexcept {
    if (status_ != Status::ok) return status_;
    const typename Block1::Propagation APA1 = b1_.propagate();
    const typename Block2::Propagation APA2 = b2_.propagate();
    const S theta = young_weight(policy_, theta_fixed_, b1_.propagated_trace(APA1) + b2_.propagated_trace(APA2),
                                      b1_.q1_trace() + b2_.q1_trace());
    typename Block1::Candidate c1;
    typename Block2::Candidate c2;
    Status s = b1_.predict_candidate(u, delta_f_nominal, APA1, theta, c1);
    if (s == Status::ok) s = b2_.predict_candidate(u, delta_f_nominal, APA2, theta, c2);
    if (s != Status::ok) return s;
    b1_.accept(c1);
    b2_.accept(c2);
    theta_ = theta;
    assemble_state();
    return Status::ok;
  }

  //! Algorithm 1 measurement update (see Eskf::update), Y in the full output order.
  [[nodiscard]] Status update(const Vec<NY, S>& Y) noexcept {
    if (status_ != Status::ok) return status_;
    // Checked here, not only per block: block 1 could otherwise report its own failure for a Y
    // whose non-finite entries sit in block 2's outputs.
    if (!all_finite(Y)) return Status::non_finite_input;
    Vec<NY1, S> Y1;
    Vec<NY2, S> Y2;
    for (int i = 0; i < NY1; ++i) Y1(i) = Y(y1_[i]);
    for (int i = 0; i < NY2; ++i) Y2(i) = Y(y2_[i]);
    typename Block1::Candidate c1;
    typename Block2::Candidate c2;
    Status s = b1_.update_candidate(Y1, c1);
    if (s == Status::ok) s = b2_.update_candidate(Y2, c2);
    if (s != Status::ok) return s;
    b1_.accept(c1);
    b2_.accept(c2);
    assemble_state();
    return Status::ok;
  }

  //! X̂ in the full state order.
  const State& state() const noexcept { return x_; }
  //! P in the full state order (assembled; the cross-block entries are zero).
  Covariance covariance() const noexcept {
    Covariance P = Covariance::Zero();
    const typename Block1::Covariance P1 = b1_.covariance();
    const typename Block2::Covariance P2 = b2_.covariance();
    for (int i = 0; i < N1; ++i)
      for (int j = 0; j < N1; ++j) P(s1_[i], s1_[j]) = P1(i, j);
    for (int i = 0; i < N2; ++i)
      for (int j = 0; j < N2; ++j) P(s2_[i], s2_[j]) = P2(i, j);
    return P;
  }
  //! P(idx, idx) without assembling P.
  template <int K>
  Mat<K, K, S> covariance_of(const std::array<int, K>& idx) const noexcept {
    Mat<K, K, S> out = Mat<K, K, S>::Zero();
    for (int a = 0; a < K; ++a)
      for (int b = 0; b < K; ++b) {
        const Where wa = where(idx[a]), wb = where(idx[b]);
        if (wa.block != wb.block || wa.block == 0) continue;
        out(a, b) = wa.block == 1 ? b1_.covariance_entry(wa.local, wb.local) : b2_.covariance_entry(wa.local, wb.local);
      }
    return out;
  }
  S theta() const noexcept { return theta_; }
  long psd_projections() const noexcept { return b1_.psd_projections() + b2_.psd_projections(); }
  const Block1& block1() const noexcept { return b1_; }
  const Block2& block2() const noexcept { return b2_; }

  //! Overwrites the estimate. non_finite_input for non-finite values, invalid_parameter when P
  //! couples the blocks (this filter cannot hold that) or a block refuses its part (EskfUd: not
  //! PSD); nothing changes in any case.
  [[nodiscard]] Status set_estimate(const State& x, const Covariance& P) noexcept {
    if (!all_finite(x) || !all_finite(P)) return Status::non_finite_input;
    for (int i = 0; i < N1; ++i)
      for (int j = 0; j < N2; ++j)
        if (P(s1_[i], s2_[j]) != S(0) || P(s2_[j], s1_[i]) != S(0)) return Status::invalid_parameter;
    typename Block1::State x1;
    typename Block1::Covariance P1;
    typename Block2::State x2;
    typename Block2::Covariance P2;
    for (int i = 0; i < N1; ++i) {
      x1(i) = x(s1_[i]);
      for (int j = 0; j < N1; ++j) P1(i, j) = P(s1_[i], s1_[j]);
    }
    for (int i = 0; i < N2; ++i) {
      x2(i) = x(s2_[i]);
      for (int j = 0; j < N2; ++j) P2(i, j) = P(s2_[i], s2_[j]);
    }
    typename Block1::Candidate c1;
    typename Block2::Candidate c2;
    Status s = b1_.estimate_candidate(x1, P1, c1);
    if (s == Status::ok) s = b2_.estimate_candidate(x2, P2, c2);
    if (s != Status::ok) return s;
    b1_.accept(c1);
    b2_.accept(c2);
    assemble_state();
    return Status::ok;
  }

  //! Eskf::replace_substate in full-state indices; all K states must lie in one block
  //! (invalid_parameter otherwise, nothing changed).
  template <int K>
  [[nodiscard]] Status replace_substate(const std::array<int, K>& idx, const Vec<K, S>& x_o, const Mat<K, K, S>& P_o) noexcept {
    std::array<int, K> local{};
    int block = 0;
    for (int a = 0; a < K; ++a) {
      const Where w = where(idx[a]);
      if (w.block == 0 || (block != 0 && w.block != block)) return Status::invalid_parameter;
      block = w.block;
      local[a] = w.local;
    }
    const Status s = block == 1 ? b1_.template replace_substate<K>(local, x_o, P_o)
                                 : b2_.template replace_substate<K>(local, x_o, P_o);
    if (s == Status::ok) assemble_state();
    return s;
  }

 private:
  struct Where {
    int block;  //!< 1, 2, or 0 when out of range
    int local;
  };
  Where where(int i) const noexcept {
    if (i < 0 || i >= N) return {0, 0};
    return {block_of_[i], local_of_[i]};
  }

  //! Index maps from the partition; invalid_parameter unless it lists distinct in-range indices.
  Status split(const Partition& part) noexcept {
    block_of_.fill(0);
    for (int i = 0; i < N1; ++i) {
      const int k = part.states[i];
      if (k < 0 || k >= N || block_of_[k] != 0) return Status::invalid_parameter;
      block_of_[k] = 1;
      local_of_[k] = i;
      s1_[i] = k;
    }
    for (int k = 0, n = 0; k < N; ++k)
      if (block_of_[k] == 0) {
        block_of_[k] = 2;
        local_of_[k] = n;
        s2_[n++] = k;
      }
    std::array<bool, NY> in1{};
    for (int i = 0; i < NY1; ++i) {
      const int k = part.outputs[i];
      if (k < 0 || k >= NY || in1[k]) return Status::invalid_parameter;
      in1[k] = true;
      y1_[i] = k;
    }
    for (int k = 0, n = 0; k < NY; ++k)
      if (!in1[k]) y2_[n++] = k;
    return Status::ok;
  }

  template <int M, int MY>
  static EskfParams<M, NU, NL, MY, S> sub_params(const Params& p, const std::array<int, M>& s,
                                                const std::array<int, MY>& y) noexcept {
    EskfParams<M, NU, NL, MY, S> b;
    for (int i = 0; i < M; ++i) {
      for (int j = 0; j < M; ++j) {
        b.A_d(i, j) = p.A_d(s[i], s[j]);
        b.P0(i, j) = p.P0(s[i], s[j]);
      }
      b.B_d.row(i) = p.B_d.row(s[i]);
      b.B_e.row(i) = p.B_e.row(s[i]);
      b.x0(i) = p.x0(s[i]);
    }
    for (int i = 0; i < MY; ++i) {
      for (int j = 0; j < M; ++j) b.C_d(i, j) = p.C_d(y[i], s[j]);
      for (int j = 0; j < MY; ++j) b.R(i, j) = p.R(y[i], y[j]);
    }
    b.q = p.q;
    b.S = p.S;
    b.theta_policy = p.theta_policy;
    b.period_s = p.period_s;
    return b;
  }

  //! True when nothing couples the blocks: A_d, P_0, B_e diag(q) B_eᵀ and B_d S B_dᵀ have no
  //! cross-block entries, C_d maps each block's states to its own outputs only, R is block-diagonal.
  bool uncoupled(const Params& p) const noexcept {
    const Mat<N, N, S> Q1 = p.B_e * p.q.asDiagonal() * p.B_e.transpose();
    const Mat<N, N, S> Q2 = p.B_d * p.S * p.B_d.transpose();
    const S zero = S(0);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        if (block_of_[i] != block_of_[j] && (p.A_d(i, j) != zero || p.P0(i, j) != zero || Q1(i, j) != zero || Q2(i, j) != zero))
          return false;
    for (int i = 0; i < NY1; ++i) {
      for (int j = 0; j < N2; ++j)
        if (p.C_d(y1_[i], s2_[j]) != zero) return false;
      for (int j = 0; j < NY2; ++j)
        if (p.R(y1_[i], y2_[j]) != zero || p.R(y2_[j], y1_[i]) != zero) return false;
    }
    for (int i = 0; i < NY2; ++i)
      for (int j = 0; j < N1; ++j)
        if (p.C_d(y2_[i], s1_[j]) != zero) return false;
    return true;
  }

  void assemble_state() noexcept {
    for (int i = 0; i < N1; ++i) x_(s1_[i]) = b1_.state()(i);
    for (int i = 0; i < N2; ++i) x_(s2_[i]) = b2_.state()(i);
  }

  std::array<int, N1> s1_{};
  std::array<int, N2> s2_{};
  std::array<int, NY1> y1_{};
  std::array<int, NY2> y2_{};
  std::array<int, N> block_of_{}, local_of_{};
  Status status_;
  Block1 b1_;
  Block2 b2_;
  ThetaPolicy policy_ = ThetaPolicy::trace_optimal;
  S theta_fixed_ = S(0);
  S theta_ = S(0);
  State x_ = State::Zero();
};

//! Algorithm 1 as two uncoupled Joseph-form blocks (the reference form).
template <int N1, int N2, int NU, int NL, int NY1, int NY2>
using PartitionedEskf = PartitionedFilter<Eskf<N1, NU, NL, NY1>, Eskf<N2, NU, NL, NY2>>;

}  // namespace adcs
