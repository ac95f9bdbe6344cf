#pragma once
// Extended-state Kalman filter (ESKF), seed 004 Algorithm 1 (spec §B.4; Bai, Xue, Huang & Fang,
// Sci. China Inf. Sci. 2018), for a discrete model with an unknown, increment-bounded disturbance
// f stacked into the state:
//
//   X_{k+1} = A_d X_k + B_d (u_k + w_k) + B_e G_k,   Y_k = C_d X_k + d_k,   E[G_{k,i}²] ≤ q_i
//
// time update   X̂⁻ = A_d X̂ + B_d u + B_e Ĝ,  Ĝ_i = clip(Δf̄_i, ±√q_i)                    eq. (9)
//               P⁻ = (1+θ) A_d P A_dᵀ + (1+1/θ) 4 B_e (l diag q) B_eᵀ + B_d S B_dᵀ
// measurement   K = P⁻Cᵀ(C P⁻ Cᵀ + R)⁻¹ (Cholesky solve, never an inverse), Joseph form for P.
// N states, NU inputs, NL disturbance channels (l), NY measurements. No heap; noexcept.
//
// Cost: A_d's and C_d's nonzeros are listed once at construction and A P Aᵀ, P Cᵀ are formed
// from them (the drag-free A_d has 162 of 729 nonzeros, C_d 9 of 243), and the Joseph form is evaluated expanded,
//   (I−KC)P(I−KC)ᵀ + KRKᵀ = P − K(PCᵀ)ᵀ − (PCᵀ)Kᵀ + K(CPCᵀ + R)Kᵀ,
// the same expression for any gain K (so it keeps Joseph's robustness to a suboptimal K) without
// the two N³ products.
#include <array>
#include <cmath>
#include <cstdint>

#include <Eigen/Cholesky>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/estimate/extended_state_covariance.hpp"

namespace adcs {

template <int N, int NU, int NL, int NY>
struct EskfParams {
  Mat<N, N> A_d = Mat<N, N>::Identity();  //!< discrete state matrix (ZOH)
  Mat<N, NU> B_d = Mat<N, NU>::Zero();    //!< discrete input matrix (ZOH)
  Mat<N, NL> B_e = Mat<N, NL>::Zero();    //!< disturbance-increment selector
  Mat<NY, N> C_d = Mat<NY, N>::Zero();    //!< measurement matrix
  Vec<NL> q = Vec<NL>::Zero();            //!< bounds on E[G_i²] (spec §B.8: (max|ḟ_i| h)²), >= 0
  Mat<NU, NU> S = Mat<NU, NU>::Zero();    //!< input-noise covariance S_k (SPD or PSD)
  Mat<NY, NY> R = Mat<NY, NY>::Identity();  //!< sensor-noise covariance R_k (SPD)
  Vec<N> x0 = Vec<N>::Zero();             //!< X̂_0 (spec §B.4: 0)
  Mat<N, N> P0 = 0.01 * Mat<N, N>::Identity();  //!< P_0 (spec §B.4: 0.01 I)
  ThetaPolicy theta_policy = ThetaPolicy::trace_optimal;  //!< spec §B.4 [D]
};

template <int N, int NU, int NL, int NY>
class Eskf {
 public:
  using Params = EskfParams<N, NU, NL, NY>;
  using State = Vec<N>;
  using Covariance = Mat<N, N>;

  explicit Eskf(const Params& p) noexcept : p_(p) {
    Q1_ = 4.0 * static_cast<double>(NL) * p_.B_e * p_.q.asDiagonal() * p_.B_e.transpose();  // Q1 = 4 B_e Q B_eᵀ, Q = l diag q
    Q2_ = p_.B_d * p_.S * p_.B_d.transpose();                                                 // Q2 = B_d S B_dᵀ
    sqrt_q_ = p_.q.cwiseMax(0.0).cwiseSqrt();
    const Eigen::LLT<Mat<NY, NY>> llt(p_.R);
    const bool ok = all_finite(p_.A_d) && all_finite(p_.B_d) && all_finite(p_.B_e) && all_finite(p_.C_d) &&
                    all_finite(p_.q) && (p_.q.array() >= 0.0).all() && all_finite(p_.S) && all_finite(p_.R) &&
                    llt.info() == Eigen::Success && all_finite(p_.x0) && all_finite(p_.P0) &&
                    p_.P0.trace() > 0.0;
    status_ = ok ? Status::ok : Status::invalid_parameter;
    theta_fixed_ = p_.P0.trace() > 0.0 ? std::sqrt(Q1_.trace() / p_.P0.trace()) : 0.0;  // θ* (literal)
    A_nz_.assign(p_.A_d);
    C_nz_.assign(p_.C_d);
    reset();
  }

  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return p_; }

  //! X̂ = X̂_0, P = P_0, counters cleared.
  void reset() noexcept {
    x_ = p_.x0;
    P_ = p_.P0;
    theta_ = 0.0;
    projections_ = 0;
  }

  //! Time update with the applied input u_{k−1} and the nominal disturbance increment Δf̄
  //! (default 0: the nominal model f̄ = 0 of spec §B.8 gives Ĝ = 0). non_finite_input leaves
  //! the state untouched.   Algorithm 1 time update, eq. (9)
  [[nodiscard]] Status predict(const Vec<NU>& u, const Vec<NL>& delta_f_nominal = Vec<NL>::Zero()) noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(u) || !all_finite(delta_f_nominal)) return Status::non_finite_input;
    const Vec<NL> G_hat = delta_f_nominal.cwiseMax(-sqrt_q_).cwiseMin(sqrt_q_);  // eq. (9)
    const State x_pred = p_.A_d * x_ + p_.B_d * u + p_.B_e * G_hat;
    const Covariance APA = sandwich_A(P_);
    const double theta = young_weight<N>(p_.theta_policy, theta_fixed_, APA, Q1_);
    Covariance P_pred = bounded_increment_prediction<N>(APA, Q1_, Q2_, theta);
    if (!all_finite(x_pred) || !all_finite(P_pred)) return Status::out_of_range;
    symmetrize_and_flush<N>(P_pred);  // a sum of PSD terms; the update checks the cone
    x_ = x_pred;
    P_ = P_pred;
    theta_ = theta;
    return Status::ok;
  }

  //! Measurement update with Y_k (Joseph form). non_finite_input / ill_conditioned leave the
  //! state untouched.   Algorithm 1 measurement update
  [[nodiscard]] Status update(const Vec<NY>& Y) noexcept {
    if (status_ != Status::ok) return status_;
    if (!all_finite(Y)) return Status::non_finite_input;
    const Mat<N, NY> PCt = C_nz_.mul_by_transpose(P_);  // P Cᵀ (C a selector: 9 of 243)
    const Mat<NY, NY> S_y = p_.C_d * PCt + p_.R;
    const Eigen::LLT<Mat<NY, NY>> llt(S_y);
    if (llt.info() != Eigen::Success) return Status::ill_conditioned;
    const Mat<N, NY> K = llt.solve(PCt.transpose()).transpose();  // K = P Cᵀ S_y⁻¹ (S_y symmetric)
    const State x_new = x_ + K * (Y - p_.C_d * x_);
    const Mat<N, N> KPCt = K * PCt.transpose();
    Covariance P_new = P_ - KPCt - KPCt.transpose() + K * (S_y * K.transpose());  // Joseph, expanded
    if (!all_finite(x_new) || !all_finite(P_new)) return Status::out_of_range;
    projections_ += keep_psd<N>(P_new);
    x_ = x_new;
    P_ = P_new;
    return Status::ok;
  }

  const State& state() const noexcept { return x_; }
  const Covariance& covariance() const noexcept { return P_; }
  //! θ used by the last prediction (0 when no channel has an increment bound).
  double theta() const noexcept { return theta_; }
  //! How many times a covariance had to be projected back onto the PSD cone.
  long psd_projections() const noexcept { return projections_; }

  //! Overwrites the estimate (fusion, Algorithm 3). Rejects non-finite values (nothing changed).
  [[nodiscard]] Status set_estimate(const State& x, const Covariance& P) noexcept {
    if (!all_finite(x) || !all_finite(P)) return Status::non_finite_input;
    x_ = x;
    P_ = P;
    return Status::ok;
  }

 private:
  //! A P Aᵀ from A's nonzeros: M = P Aᵀ column by column, then A M = (Mᵀ Aᵀ)ᵀ the same way
  //! (P symmetric, so Mᵀ = A P); column operations are contiguous in Eigen's column-major storage.
  Covariance sandwich_A(const Covariance& P) const noexcept {
    const Covariance M = A_nz_.mul_by_transpose(P);  // P Aᵀ
    return A_nz_.mul_by_transpose(Covariance(M.transpose()));  // (A P Aᵀ)ᵀ
  }

  //! The nonzeros of a fixed R x N matrix X, listed once, to form Y Xᵀ for an N-column Y.
  template <int R>
  struct Nonzeros {
    std::array<std::uint16_t, R * N> row{}, col{};
    std::array<double, R * N> val{};
    int count = 0;
    void assign(const Mat<R, N>& X) noexcept {
      count = 0;
      for (int j = 0; j < N; ++j)
        for (int i = 0; i < R; ++i)
          if (X(i, j) != 0.0) {
            row[count] = static_cast<std::uint16_t>(i);
            col[count] = static_cast<std::uint16_t>(j);
            val[count] = X(i, j);
            ++count;
          }
    }
    //! Y Xᵀ column by column: (Y Xᵀ)(:, i) = Σ_j X(i, j) Y(:, j) (contiguous, column-major).
    template <int NR>
    Mat<NR, R> mul_by_transpose(const Mat<NR, N>& Y) const noexcept {
      Mat<NR, R> out = Mat<NR, R>::Zero();
      for (int k = 0; k < count; ++k) out.col(row[k]) += val[k] * Y.col(col[k]);
      return out;
    }
  };

  Params p_;
  Nonzeros<N> A_nz_;
  Nonzeros<NY> C_nz_;
  Covariance Q1_ = Covariance::Zero(), Q2_ = Covariance::Zero();
  Vec<NL> sqrt_q_ = Vec<NL>::Zero();
  double theta_fixed_ = 0.0;
  Status status_ = Status::ok;
  State x_ = State::Zero();
  Covariance P_ = Covariance::Identity();
  double theta_ = 0.0;
  long projections_ = 0;
};

}  // namespace adcs
