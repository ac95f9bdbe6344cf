#pragma once
// Extended-state Kalman filter (ESKF), seed 004 Algorithm 1 (spec §B.4; Bai, Xue, Huang & Fang,
// Sci. China Inf. Sci. 2018), for a discrete model with an unknown, increment-bounded disturbance
// f stacked into the state:
//
//   X_{k+1} = A_d X_k + B_d (u_k + w_k) + B_e G_k,   Y_k = C_d X_k + d_k,   E[G_{k,i}²] ≤ q_i
//
// time update   X̂⁻ = A_d X̂ + B_d u + B_e Ĝ,  Ĝ_i = clip(Δf̄_i, ±√q_i)                    seed 004 eq. (9)
//               P⁻ = (1+θ) A_d P A_dᵀ + (1+1/θ) 4 B_e (l diag q) B_eᵀ + B_d S B_dᵀ
// measurement   K = P⁻Cᵀ(C P⁻ Cᵀ + R)⁻¹ (Cholesky solve, never an inverse), Joseph form for P.
// N states, NU inputs, NL disturbance channels (l), NY measurements. No heap; noexcept.
//
// Cost: A_d's and C_d's nonzeros are listed once at construction and A P Aᵀ, P Cᵀ are formed
// from them (the drag-free A_d has 162 of 729 nonzeros, C_d 9 of 243), and the Joseph form is
// evaluated expanded (update_candidate): the same expression for any gain K, so it keeps Joseph's
// robustness to a suboptimal K, without the two N³ products.
#include <array>
#include <cmath>
#include <cstdint>

#include <Eigen/Cholesky>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/component.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/estimate/extended_state_covariance.hpp"
#include "adcs/math/sparse_rows.hpp"

namespace adcs {

//! The model (A_d, B_d, B_e, C_d) and R have no default: NaN until set, so a forgotten matrix is
//! refused (status() == invalid_parameter). q = 0 and S = 0 are real choices (no increment bound,
//! no input noise: spec §B.8's T_Dtm channel has q = 0); X̂_0, P_0 and θ are spec §B.4's.
//! Sc is the scalar (issue 19: double by default; the U-D form also runs in float, EskfUd).
template <int N, int NU, int NL, int NY, class Sc = double>
struct EskfParams {
  Mat<N, N, Sc> A_d = Mat<N, N, Sc>::Constant(unset_v<Sc>);    //!< discrete state matrix (ZOH), no default
  Mat<N, NU, Sc> B_d = Mat<N, NU, Sc>::Constant(unset_v<Sc>);  //!< discrete input matrix (ZOH), no default
  Mat<N, NL, Sc> B_e = Mat<N, NL, Sc>::Constant(unset_v<Sc>);  //!< disturbance-increment selector, no default
  Mat<NY, N, Sc> C_d = Mat<NY, N, Sc>::Constant(unset_v<Sc>);  //!< measurement matrix, no default
  Vec<NL, Sc> q = Vec<NL, Sc>::Zero();          //!< bounds on E[G_i²] (spec §B.8: (max|ḟ_i| h)²), >= 0
  Mat<NU, NU, Sc> S = Mat<NU, NU, Sc>::Zero();  //!< input-noise covariance S_k (symmetric PSD)
  Mat<NY, NY, Sc> R = Mat<NY, NY, Sc>::Constant(unset_v<Sc>);  //!< sensor-noise covariance R_k (SPD), no default
  Vec<N, Sc> x0 = Vec<N, Sc>::Zero();           //!< X̂_0 (spec §B.4: 0)
  Mat<N, N, Sc> P0 = Sc(0.01) * Mat<N, N, Sc>::Identity();  //!< P_0 (spec §B.4: 0.01 I), symmetric PSD, tr > 0
  ThetaPolicy theta_policy = ThetaPolicy::trace_optimal;  //!< spec §B.4 [D]
  Sc period_s = unset_v<Sc>;  //!< [s] h, the period A_d and B_d were discretised at, no default

  //! The same parameters in the scalar T, each value rounded once (narrow_scalar: beyond T's
  //! range → ±Inf, refused by the filter's check).
  template <class T>
  EskfParams<N, NU, NL, NY, T> cast() const noexcept {
    EskfParams<N, NU, NL, NY, T> out;
    const auto c = [](const auto& m) { return m.unaryExpr([](Sc v) { return narrow_scalar<T>(v); }); };
    out.A_d = c(A_d);
    out.B_d = c(B_d);
    out.B_e = c(B_e);
    out.C_d = c(C_d);
    out.q = c(q);
    out.S = c(S);
    out.R = c(R);
    out.x0 = c(x0);
    out.P0 = c(P0);
    out.theta_policy = theta_policy;
    out.period_s = narrow_scalar<T>(period_s);
    return out;
  }
};

//! One filter sample: the input applied over the last period, the nominal disturbance increment
//! and the measurement taken now.
template <int NU, int NL, int NY, class S = double>
struct EskfInput {
  Vec<NU, S> u = Vec<NU, S>::Zero();                //!< u_{k−1}, applied over the last period
  Vec<NL, S> delta_f_nominal = Vec<NL, S>::Zero();  //!< Δf̄ (0: the nominal model f̄ = 0 of spec §B.8)
  Vec<NY, S> y = Vec<NY, S>::Zero();                //!< Y_k
};

template <int N, class S = double>
struct EskfOutput {
  Vec<N, S> x_hat = Vec<N, S>::Zero();  //!< X̂_k (the prediction alone when the update was rejected)
};

template <class S = double>
struct EskfDiagnosticsT {
  Status predict = Status::ok;  //!< the time update's status
  Status update = Status::ok;   //!< the measurement update's (the time update's when it failed)
  S theta = S(0);               //!< [-] θ_k of the time update
};
using EskfDiagnostics = EskfDiagnosticsT<double>;

//! The parameter check both forms of Algorithm 1 (Eskf, EskfUd) make: A_d, B_d, B_e, C_d and
//! X̂_0 finite; q finite >= 0; S symmetric PSD; R symmetric positive definite; P_0 symmetric PSD
//! with tr P_0 > 0 (θ* divides by it); period_s finite > 0.
template <int N, int NU, int NL, int NY, class S>
bool valid(const EskfParams<N, NU, NL, NY, S>& p) noexcept {
  return all_finite(p.A_d) && all_finite(p.B_d) && all_finite(p.B_e) && all_finite(p.C_d) && finite_nonnegative(p.q) &&
         symmetric_positive_semidefinite<NU, S>(p.S) && symmetric_positive_definite<NY, S>(p.R) && all_finite(p.x0) &&
         symmetric_positive_semidefinite<N, S>(p.P0) && p.P0.trace() > S(0) && finite_positive(p.period_s);
}

namespace detail {
//! out += B v, for B dense (Eigen's product) or from its nonzeros (SparseRows::add_product).
template <int N, int M, class S>
void add_product(const Mat<N, M, S>& B, const Vec<M, S>& v, Vec<N, S>& out) noexcept {
  out.noalias() += B * v;
}
template <int N, int M, class S>
void add_product(const SparseRows<N, M, S>& B, const Vec<M, S>& v, Vec<N, S>& out) noexcept {
  B.add_product(v, out);
}

//! X̂⁻ = A_d X̂ + B_d u + B_e Ĝ with Ĝ_i = clip(Δf̄_i, ±√q_i), A_d from its nonzeros; B_d and B_e
//! dense matrices or their nonzeros (SparseRows; EskfUd: the drag-free blocks' B_d and B_e are 1/3
//! and 1/27 nonzero).   seed 004 eq. (9)
template <int N, int NU, int NL, class S, class BdT, class BeT>
Vec<N, S> extended_state_prediction(const SparseRows<N, N, S>& A_nz, const BdT& B_d, const BeT& B_e,
                                    const Vec<NL, S>& sqrt_q, const Vec<N, S>& x, const Vec<NU, S>& u,
                                    const Vec<NL, S>& delta_f_nominal) noexcept {
  const Vec<NL, S> G_hat = delta_f_nominal.cwiseMax(-sqrt_q).cwiseMin(sqrt_q);  // seed 004 eq. (9)
  Vec<N, S> out = A_nz.mul_by_transpose(Mat<1, N, S>(x.transpose())).transpose();  // A_d x (sparse)
  add_product<N, NU, S>(B_d, u, out);
  add_product<N, NL, S>(B_e, G_hat, out);
  return out;
}

//! step() of the filters that have predict() and update(): the time update, then the measurement
//! update; a rejected measurement leaves the prediction in place (the filter coasts, as a flight
//! estimator does when a sensor sample is bad), a rejected time update leaves everything. The
//! output is always the filter's current estimate, which stays finite.
template <class Filter, class In, int N, class S>
Status estimator_sample(Filter& f, const In& in, EskfOutput<N, S>& out, EskfDiagnosticsT<S>* diag) noexcept {
  const Status sp = f.predict(in.u, in.delta_f_nominal);
  const Status su = usable(sp) ? f.update(in.y) : sp;
  out.x_hat = f.state();
  if (diag) {
    diag->predict = sp;
    diag->update = su;
    diag->theta = f.theta();
  }
  return usable(sp) ? su : sp;
}

//! replace_substate's input check (both forms): indices distinct and in [0, N) (invalid_parameter),
//! values finite (non_finite_input).
template <int N, int K, class S>
Status substate_check(const std::array<int, K>& idx, const Vec<K, S>& x_o, const Mat<K, K, S>& P_o) noexcept {
  for (int a = 0; a < K; ++a) {
    if (idx[a] < 0 || idx[a] >= N) return Status::invalid_parameter;
    for (int b = 0; b < a; ++b)
      if (idx[a] == idx[b]) return Status::invalid_parameter;
  }
  if (!all_finite(x_o) || !all_finite(P_o)) return Status::non_finite_input;
  return Status::ok;
}

//! What both forms of Algorithm 1 (Eskf, EskfUd) do with their two-phase interface: each public
//! operation computes a candidate from the current estimate and applies it only when it succeeded,
//! so a refused predict(), update() or set_estimate() changes nothing. Derived provides status(),
//! params(), theta_fixed(), propagate(), propagated_trace(), q1_trace(), predict_candidate(),
//! update_candidate(), estimate_candidate(), accept() and its Candidate.
template <class Derived, int N, int NU, int NL, int NY, class S = double>
class CandidateFilter {
 public:
  //! One sample: predict(in.u, in.delta_f_nominal), then update(in.y) (estimator_sample).
  [[nodiscard]] Status step(const EskfInput<NU, NL, NY, S>& in, EskfOutput<N, S>& out,
                            EskfDiagnosticsT<S>* diag = nullptr) noexcept {
    return estimator_sample(self(), in, out, diag);
  }

  //! Time update with the applied input u_{k−1} and the nominal disturbance increment Δf̄
  //! (default 0: the nominal model f̄ = 0 of spec §B.8 gives Ĝ = 0), θ_k from tr(A_d P A_dᵀ) and
  //! tr Q1 (or θ*). non_finite_input / out_of_range leave the state untouched.   seed 004 eq. (9)
  [[nodiscard]] Status predict(const Vec<NU, S>& u, const Vec<NL, S>& delta_f_nominal = Vec<NL, S>::Zero()) noexcept {
    Derived& d = self();
    if (d.status() != Status::ok) return d.status();
    const typename Derived::Propagation AP = d.propagate();
    const S theta =
        young_weight(d.params().theta_policy, d.theta_fixed(), d.propagated_trace(AP), d.q1_trace());
    typename Derived::Candidate c;
    const Status s = d.predict_candidate(u, delta_f_nominal, AP, theta, c);
    if (s == Status::ok) d.accept(c);
    return s;
  }

  //! Measurement update with Y_k (see Derived::update_candidate for the form and its statuses);
  //! a refused update leaves the state untouched.   Algorithm 1 measurement update
  [[nodiscard]] Status update(const Vec<NY, S>& Y) noexcept {
    Derived& d = self();
    if (d.status() != Status::ok) return d.status();
    typename Derived::Candidate c;
    const Status s = d.update_candidate(Y, c);
    if (s == Status::ok) d.accept(c);
    return s;
  }

  //! Overwrites the estimate (fusion, Algorithm 3) after Derived::estimate_candidate's check;
  //! nothing changes when it refuses.
  [[nodiscard]] Status set_estimate(const Vec<N, S>& x, const Mat<N, N, S>& P) noexcept {
    Derived& d = self();
    typename Derived::Candidate c;
    const Status s = d.estimate_candidate(x, P, c);
    if (s == Status::ok) d.accept(c);
    return s;
  }

 private:
  Derived& self() noexcept { return static_cast<Derived&>(*this); }
};
}  // namespace detail

//! The Joseph form, double only: the reference the U-D form (EskfUd, also in float) is tested
//! against; its eigen projection has no float counterpart worth flying.
template <int N, int NU, int NL, int NY>
class Eskf : public detail::CandidateFilter<Eskf<N, NU, NL, NY>, N, NU, NL, NY> {
 public:
  using Scalar = double;
  using Params = EskfParams<N, NU, NL, NY>;
  using Input = EskfInput<NU, NL, NY>;
  using Output = EskfOutput<N>;
  using Diagnostics = EskfDiagnostics;
  using State = Vec<N>;
  using Covariance = Mat<N, N>;
  static constexpr int kStates = N, kInputs = NU, kChannels = NL, kOutputs = NY;

  explicit Eskf(const Params& p) noexcept : p_(p) {
    Q1_ = 4.0 * static_cast<double>(NL) * p_.B_e * p_.q.asDiagonal() * p_.B_e.transpose();  // Q1 = 4 B_e Q B_eᵀ, Q = l diag q
    Q2_ = p_.B_d * p_.S * p_.B_d.transpose();                                                 // Q2 = B_d S B_dᵀ
    Q1_ = 0.5 * (Q1_ + Q1_.transpose()).eval();  // bit-symmetric, so the prediction is too
    Q2_ = 0.5 * (Q2_ + Q2_.transpose()).eval();
    sqrt_q_ = p_.q.cwiseMax(0.0).cwiseSqrt();
    status_ = valid(p_) ? Status::ok : Status::invalid_parameter;
    theta_fixed_ = p_.P0.trace() > 0.0 ? std::sqrt(Q1_.trace() / p_.P0.trace()) : 0.0;  // θ* (literal)
    A_nz_.assign(p_.A_d);
    C_nz_.assign(p_.C_d);
    reset();
  }

  //! ok, or invalid_parameter: A_d, B_d, B_e, C_d or X̂_0 not finite (unset); q not finite or
  //! < 0; S not symmetric PSD; R not symmetric positive definite (the innovation covariance must be
  //! invertible for any P); P_0 not symmetric PSD or tr P_0 = 0 (θ* divides by it); period_s not
  //! finite > 0. A refused filter answers invalid_parameter from predict(), update() and step()
  //! with its estimate untouched.
  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }
  double period_s() const noexcept { return p_.period_s; }

  //! step(), predict(), update(), set_estimate(): detail::CandidateFilter.
  //! θ* = √(tr Q1 / tr P_0), the fixed θ of ThetaPolicy::fixed_initial.
  double theta_fixed() const noexcept { return theta_fixed_; }

  //! X̂ = X̂_0, P = P_0, counters cleared.
  void reset() noexcept {
    x_ = p_.x0;
    P_ = p_.P0;
    theta_ = 0.0;
    projections_ = 0;
  }

  // ---- Two-phase form, for filters composed of several Eskf blocks (PartitionedEskf): each
  // block computes a candidate, and the candidates are accepted only when every block succeeded.

  //! A result of predict_candidate / update_candidate, not yet applied.
  struct Candidate {
    State x;
    Covariance P;
    double theta = -1.0;  //!< θ of a prediction; < 0 for an update
    bool projected = false;
  };

  //! A_d P A_dᵀ from the current P (the first half of the time update; θ_k is taken from it) and
  //! its trace: the block interface of PartitionedFilter and of detail::CandidateFilter.
  using Propagation = Covariance;
  Propagation propagate() const noexcept { return sandwich_A(P_); }
  static double propagated_trace(const Propagation& APA) noexcept { return APA.trace(); }
  //! tr Q1, Q1 = 4 B_e (l diag q) B_eᵀ (θ_k = √(tr Q1 / tr APA)).
  double q1_trace() const noexcept { return Q1_.trace(); }

  //! The time update with a given A P Aᵀ and θ (see predict).
  [[nodiscard]] Status predict_candidate(const Vec<NU>& u, const Vec<NL>& delta_f_nominal, const Propagation& APA,
                                         double theta, Candidate& out) const noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(u) || !all_finite(delta_f_nominal)) return Status::non_finite_input;
    out.x = detail::extended_state_prediction<N, NU, NL>(A_nz_, p_.B_d, p_.B_e, sqrt_q_, x_, u, delta_f_nominal);
    out.P = bounded_increment_prediction<N>(APA, Q1_, Q2_, theta);
    if (!all_finite(out.x) || !all_finite(out.P)) return Status::out_of_range;
    flush_negligible<N>(out.P);  // symmetric PSD terms (APA mirrored); the update checks the cone
    out.theta = theta;
    out.projected = false;
    return Status::ok;
  }

  //! The measurement update (update()). non_finite_input / singular (C P Cᵀ + R not positive
  //! definite) / out_of_range (overflow) change nothing. (singular, not ill_conditioned: that
  //! status is usable(), "a regularised result was returned", and nothing is returned here.)
  //! Joseph form, expanded, with W = K S_y − P Cᵀ:
  //!   (I−KC)P(I−KC)ᵀ + KRKᵀ = P − K(PCᵀ)ᵀ − (PCᵀ)Kᵀ + K S_y Kᵀ = P − K(PCᵀ)ᵀ + W Kᵀ
  //! (exact for any K; W is the gain's residual, ~0 for the optimal K). K = P Cᵀ S_y⁻¹ by two
  //! triangular solves with the Cholesky factor of S_y (never an inverse); only the lower
  //! triangle of the symmetric result is formed, then mirrored.
  [[nodiscard]] Status update_candidate(const Vec<NY>& Y, Candidate& out) const noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(Y)) return Status::non_finite_input;
    const Mat<N, NY> PCt = C_nz_.mul_by_transpose(P_);  // P Cᵀ (C a selector: 9 of 243)
    const Mat<NY, NY> S_y = p_.R + C_nz_.mul_by_transpose(Mat<NY, N>(PCt.transpose()));  // C P Cᵀ + R
    const Eigen::LLT<Mat<NY, NY>> llt(S_y);
    if (llt.info() != Eigen::Success) return Status::singular;  // nothing applied: not usable()
    const Mat<N, NY> K = solve_gain(llt.matrixLLT(), PCt);
    const Vec<NY> innovation = Y - C_nz_.mul_by_transpose(Mat<1, N>(x_.transpose())).transpose();
    out.x = x_;
    out.x.noalias() += K * innovation;
    Mat<N, 2 * NY> U, V;  // P − K PCtᵀ + W Kᵀ = P − U Vᵀ with U = [K, −W], V = [PCt, K]
    U.template leftCols<NY>() = K;
    U.template rightCols<NY>() = PCt;
    U.template rightCols<NY>().noalias() -= K * S_y;  // −W
    V.template leftCols<NY>() = PCt;
    V.template rightCols<NY>() = K;
    out.P = P_;
    out.P.noalias() -= U.lazyProduct(V.transpose());
    out.P.template triangularView<Eigen::StrictlyUpper>() = out.P.transpose();  // exact symmetry
    if (!all_finite(out.x) || !all_finite(out.P)) return Status::out_of_range;
    flush_negligible<N>(out.P);
    out.projected = project_if_not_psd<N>(out.P);
    // The eigen-projection of a finite P with entries near 1e308 (after set_estimate or
    // replace_substate with absurd values) can itself overflow: check again.
    if (out.projected && !all_finite(out.P)) return Status::out_of_range;
    out.theta = -1.0;
    return Status::ok;
  }

  //! Applies a candidate computed from the current estimate.
  void accept(const Candidate& c) noexcept {
    x_ = c.x;
    P_ = c.P;
    if (c.theta >= 0.0) theta_ = c.theta;
    projections_ += c.projected ? 1 : 0;
  }

  const State& state() const noexcept { return x_; }
  const Covariance& covariance() const noexcept { return P_; }
  double covariance_entry(int i, int j) const noexcept { return P_(i, j); }
  //! θ used by the last prediction (0 when no channel has an increment bound).
  double theta() const noexcept { return theta_; }
  //! How many times a covariance had to be projected back onto the PSD cone.
  long psd_projections() const noexcept { return projections_; }

  //! set_estimate's check, as a candidate (PartitionedFilter sets both blocks or neither):
  //! non-finite values are refused (non_finite_input).
  [[nodiscard]] Status estimate_candidate(const State& x, const Covariance& P, Candidate& out) const noexcept {
    if (!all_finite(x) || !all_finite(P)) return Status::non_finite_input;
    out.x = x;
    out.P = P;
    out.theta = -1.0;
    out.projected = false;
    return Status::ok;
  }

  //! Overwrites K states in place (fusion, Algorithm 3, seed 004 eqs. (40)-(41)): x(idx) = x_o, the rows and
  //! columns idx of P zeroed, P(idx, idx) = P_o. Indices must be distinct and in range
  //! (invalid_parameter) and the values finite (non_finite_input); nothing changes otherwise.
  template <int K>
  [[nodiscard]] Status replace_substate(const std::array<int, K>& idx, const Vec<K>& x_o, const Mat<K, K>& P_o) noexcept {
    if (const Status s = detail::substate_check<N, K>(idx, x_o, P_o); s != Status::ok) return s;
    for (int a = 0; a < K; ++a) {
      x_(idx[a]) = x_o(a);
      P_.row(idx[a]).setZero();
      P_.col(idx[a]).setZero();
    }
    for (int a = 0; a < K; ++a)
      for (int b = 0; b < K; ++b) P_(idx[a], idx[b]) = P_o(a, b);
    return Status::ok;
  }

 private:
  //! A P Aᵀ from A's nonzeros: M = P Aᵀ column by column, then A M = (Mᵀ Aᵀ)ᵀ the same way
  //! (P symmetric, so Mᵀ = A P); column operations are contiguous in Eigen's column-major storage.
  Covariance sandwich_A(const Covariance& P) const noexcept {
    const Covariance M = A_nz_.mul_by_transpose(P);  // P Aᵀ
    Covariance out = A_nz_.mul_by_transpose(Covariance(M.transpose()));  // (A P Aᵀ)ᵀ
    out.template triangularView<Eigen::StrictlyUpper>() = out.transpose();  // exact symmetry
    return out;
  }

  //! K = PCt S_y⁻¹ from the Cholesky factor L of S_y = L Lᵀ (lower triangle of the LLT): solve
  //! Z Lᵀ = PCt for Z = K L column by column (increasing), then K L = Z (decreasing).
  static Mat<N, NY> solve_gain(const Mat<NY, NY>& L, const Mat<N, NY>& PCt) noexcept {
    Mat<N, NY> Z = PCt;  // Z Lᵀ = PCt  →  columns in increasing order
    for (int m = 0; m < NY; ++m) {
      for (int c = 0; c < m; ++c) Z.col(m) -= L(m, c) * Z.col(c);
      Z.col(m) /= L(m, m);
    }
    Mat<N, NY> K = Z;  // K L = Z  →  columns in decreasing order
    for (int m = NY - 1; m >= 0; --m) {
      for (int c = m + 1; c < NY; ++c) K.col(m) -= L(c, m) * K.col(c);
      K.col(m) /= L(m, m);
    }
    return K;
  }

  Params p_;
  SparseRows<N, N> A_nz_;
  SparseRows<NY, N> C_nz_;
  Covariance Q1_ = Covariance::Zero(), Q2_ = Covariance::Zero();
  Vec<NL> sqrt_q_ = Vec<NL>::Zero();
  double theta_fixed_ = 0.0;
  Status status_ = Status::ok;
  State x_ = State::Zero();
  Covariance P_ = Covariance::Identity();
  double theta_ = 0.0;
  long projections_ = 0;
};

ADCS_ASSERT_COMPONENT(Eskf<3, 1, 1, 1>);

}  // namespace adcs
