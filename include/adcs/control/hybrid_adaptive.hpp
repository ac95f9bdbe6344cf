#pragma once
// Adaptive MIMO attitude tracking for a hybrid CMG + reaction-wheel spacecraft with installation
// deviations (seed 001, Ye, Sun & Liu 2016), spec §A.3 steps 1-14:
//   σ̈ = F*(σ,σ̇) + G*(σ,σ̇) u,  u = [γ̇ (M) rad/s; Ω̇_w (N) rad/s²]           seed 001 eq. (8)
//   F* = F*n + Y_F Θ_F,  G* = G*n + Y_G Θ_G  (Θ_F = H_I^Δ, Θ_Gk = axis deviations)  seed 001 eqs. (15)-(20)
//   u = X⁺ v,  X = G*n + Y_G Θ̂_G,  v = −K e − F*n − Y_F Θ̂_F + σ̈_d                   seed 001 eq. (24)
//   Θ̂̇_F = α_F Y_Fᵀ B0ᵀ P e,  Θ̂̇_Gk = Proj(Θ̂_Gk, Y_Gkᵀ B0ᵀ P e u_k)               seed 001 eqs. (25)-(26)
// K from the closed-loop eigenvalues and P from A_1ᵀP + PA_1 = −Q_L (the gains) are designed
// once, before the first step; step() is the per-sample arithmetic, estimates integrated by
// explicit Euler at the control period (spec §A.3 step 13) with the discrete radial safeguard
// (counted). α_F = α_G = 0 gives the non-adaptive baseline.
// Two constructors: from the parameters alone (the gains designed in double at construction,
// design_hybrid_adaptive_gains), or from the parameters and gains designed on the ground
// (HybridAdaptiveGains, checked on entry: P SPD, A_1ᵀP + PA_1 = −Q_L, A_1 Hurwitz). The second is
// what a flight build uploads: no pole placement, no Schur-based Lyapunov solve and no double
// arithmetic on board (a float law on a single-precision FPU compiles none of them).
// Scalar (issue 19): HybridAdaptive<M, N, S>. The design runs in double and is rounded to S once;
// J_n = J_tr(0) and its inverse are formed in S from the nominal geometry; step() runs in S.
#include <array>
#include <cstdint>
#include <limits>

#include "adcs/actuator/steering.hpp"
#include "adcs/adapt/normalized_step.hpp"
#include "adcs/adapt/projection.hpp"
#include "adcs/core/component.hpp"
#include "adcs/core/failure_hook.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
#include "adcs/math/lyapunov.hpp"
#include "adcs/math/mrp.hpp"
#include "adcs/math/place.hpp"
#include "adcs/plant/vscmg_cluster.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"

namespace adcs {

//! Closed-loop eigenvalues of seed 001 §4 / spec §A.4 #22, one pair per axis:
//! x {−0.2 ± 0.2i}, y {−0.3 ± 0.3i}, z {−0.2√2, −0.3√2}.
inline AxisPoles<3> seed001_axis_poles() noexcept {
  const double r2 = 1.4142135623730950488;
  return AxisPoles<3>{{{{{-0.2, 0.2}, {-0.2, -0.2}}},
                       {{{-0.3, 0.3}, {-0.3, -0.3}}},
                       {{{-0.2 * r2, 0.0}, {-0.3 * r2, 0.0}}}}};
}

//! Defaults: seed 001 §4 (poles, Q_L, α, β, δ), spec §A.3/§A.5 (H_I^n = 0, T_c = 1 ms), ours
//! (max_step_gain, docs/DECISIONS.md). The nominal geometry has no default (VscmgGeometry is NaN
//! until set, e.g. pyramid_4cmg_3rw_nominal()): a default set is refused.
template <int M, int N, class S = double>
struct HybridAdaptiveParams {
  VscmgGeometry<M, N, S> nominal;          //!< nominal geometry: all the controller knows (no default)
  AxisPoles<3> poles = seed001_axis_poles();  //!< eig(A_1), one pair per axis (seed 001 §4); design, double
  Mat<6, 6, S> Q_L = Mat<6, 6, S>::Identity();  //!< [-] Lyapunov weight (seed 001 §4: Q = I_6)
  S alpha_F = S(1.0e7);                    //!< [-] momentum adaptation gain (seed 001 §4)
  S alpha_G = S(1.0e3);                    //!< [-] deviation adaptation gain (seed 001 §4)
  S beta_G = S(0.05);                      //!< [-] projection radius² β_Gi (seed 001 §4)
  S delta_G = S(0.1);                      //!< [-] projection boundary layer δ_Gi (seed 001 §4)
  Vec<3, S> H_I_n = Vec<3, S>::Zero();     //!< [N m s] nominal inertial momentum H_I^n (§A.3)
  S period_s = S(1.0e-3);                  //!< [s] T_c (spec §A.5: ≥ 5 ms is unstable)
  SteeringParamsT<S> steering{};           //!< singularity-robust fallback threshold/damping
  //! After a failed step: zero gimbal rates and wheel accelerations (safe_command), or hold.
  FailurePolicy on_failure = FailurePolicy::safe_command;
  //! Estimate integration over T_c. explicit_euler is the paper's (spec §A.3 step 13, stable for
  //! T_c ≤ 3 ms on A-REF); normalized keeps the per-step loop gain below max_step_gain so the
  //! adaptation stays stable at flight rates (5-20 Hz); see adapt/normalized_step.hpp.
  AdaptationStep adaptation_step = AdaptationStep::explicit_euler;
  S max_step_gain = S(0.2);                //!< [-] λ_max of the normalized step (ours; 0.2 keeps
                                           //!< A-REF accuracy from 1 ms to 200 ms, docs/DECISIONS.md)
  //! The same parameters in another scalar (each value rounded once; validated by the controller).
  template <class T>
  HybridAdaptiveParams<M, N, T> cast() const noexcept {
    HybridAdaptiveParams<M, N, T> q;
    q.nominal = nominal.template cast<T>();
    q.poles = poles;
    q.Q_L = scalar_cast<T>(Q_L);
    q.alpha_F = narrow_scalar<T>(alpha_F);
    q.alpha_G = narrow_scalar<T>(alpha_G);
    q.beta_G = narrow_scalar<T>(beta_G);
    q.delta_G = narrow_scalar<T>(delta_G);
    q.H_I_n = scalar_cast<T>(H_I_n);
    q.period_s = narrow_scalar<T>(period_s);
    q.steering = steering.template cast<T>();
    q.on_failure = on_failure;
    q.adaptation_step = adaptation_step;
    q.max_step_gain = narrow_scalar<T>(max_step_gain);
    return q;
  }
};

//! The gains of seed 001's law (seed 001 §3, eq. (14)): K = [K_p K_d] with A_1 = A_0 − B_0 K, and P
//! with A_1ᵀP + PA_1 = −Q_L. No default (NaN: refused until set), from
//! design_hybrid_adaptive_gains on the ground or from a gain table.
template <class S = double>
struct HybridAdaptiveGains {
  Mat<3, 6, S> K = Mat<3, 6, S>::Constant(unset_v<S>);  //!< [1/s², 1/s] state feedback of σ̈ = v
  Mat<6, 6, S> P = Mat<6, 6, S>::Constant(unset_v<S>);  //!< [-] Lyapunov matrix of A_1 and Q_L
  template <class T>
  HybridAdaptiveGains<T> cast() const noexcept {
    return {scalar_cast<T>(K), scalar_cast<T>(P)};
  }
};

//! The ground design of seed 001 §3 in double: K places one eigenvalue pair per axis
//! (math/place.hpp); P solves A_1ᵀP + PA_1 = −Q_L (math/lyapunov.hpp), Q_L given in any scalar S
//! and cast to double. ok, or invalid_parameter (poles not finite conjugate pairs in the open
//! left half-plane, Q_L not SPD, the Lyapunov solve failed) with `g` untouched.
//! A template (in S) on purpose: a unit that never calls it compiles none of the Schur-based
//! solve, which a non-template inline function would instantiate wherever this header goes.
template <class S>
Status design_hybrid_adaptive_gains(const AxisPoles<3>& poles, const Mat<6, 6, S>& Q_L_in,
                                    HybridAdaptiveGains<double>& g) noexcept {
  const Mat6 Q_L = scalar_cast<double>(Q_L_in);
  Mat<3, 6> K;
  Mat6 P;
  // Hurwitz poles: s² + k_d s + k_p has both roots in the open left half-plane iff k_p, k_d > 0.
  if (place_double_integrator<3>(poles, K) != Status::ok ||
      !(K.leftCols<3>().diagonal().array() > 0.0).all() || !(K.rightCols<3>().diagonal().array() > 0.0).all())
    return Status::invalid_parameter;
  // Q_L SPD with a Hurwitz A_1 makes P SPD (seed 001 §3: A_1ᵀP + PA_1 = −Q_L).
  if (!symmetric_positive_definite<6>(Q_L) ||
      solve_continuous_lyapunov<6>(double_integrator_closed_loop<3>(K), Q_L, P) != Status::ok)
    return Status::invalid_parameter;
  g.K = K;
  g.P = P;
  return Status::ok;
}

template <int M, int N, class S = double>
struct HybridAdaptiveInput {
  AttitudeStateT<S> state{};          //!< σ_BN (not shadow-switched, spec §A.2.4), ω_BN_B
  VscmgState<M, N, S> actuators{};    //!< gimbal angles; wheel speeds (not used by the law; checked)
  MrpReferenceSampleT<S> reference{};  //!< σ_d, σ̇_d, σ̈_d
  template <class T>
  HybridAdaptiveInput<M, N, T> cast() const noexcept {
    return {state.template cast<T>(), actuators.template cast<T>(), reference.template cast<T>()};
  }
};

//! Optional per-step diagnostics (caller-owned; costs nothing when not requested).
template <int M, int N, class S = double>
struct HybridAdaptiveDiagnostics {
  Vec<6, S> e = Vec<6, S>::Zero();                 //!< [-, 1/s] tracking error [σ − σ_d; σ̇ − σ̇_d]
  Mat<3, M + N, S> X = Mat<3, M + N, S>::Zero();   //!< steering matrix G*n + Y_G Θ̂_G
  SteeringInfoT<S> steering{};                     //!< σ_min(X), mode used
  int projection_active_blocks = 0;                //!< blocks whose projection correction acted
  S theta_F_step_scale = S(1);                     //!< [-] normalized-step scale applied to Θ̂_F (1 = none)
};

template <int M, int N, class S = double>
class HybridAdaptive {
 public:
  static constexpr int L = M + N;
  using Scalar = S;
  using Params = HybridAdaptiveParams<M, N, S>;
  using Input = HybridAdaptiveInput<M, N, S>;
  using Output = VscmgRates<M, N, S>;
  using Diagnostics = HybridAdaptiveDiagnostics<M, N, S>;
  using Vec3S = Vec<3, S>;
  using Vec6S = Vec<6, S>;
  using Mat3S = Mat<3, 3, S>;

  //! The gains designed here, in double (design_hybrid_adaptive_gains), and rounded to S once.
  explicit HybridAdaptive(const Params& p) noexcept : HybridAdaptive(p, designed_gains(p)) {}

  //! Gains designed on the ground (a gain table), checked before use: K and P finite, P
  //! symmetric positive definite, the Lyapunov residual ‖A_1ᵀP + PA_1 + Q_L‖_F within
  //! kLyapunovResidualUlps rounding units of its terms (2‖A_1‖_F‖P‖_F + ‖Q_L‖_F), and
  //! −(A_1ᵀP + PA_1) positive definite, which with P SPD proves A_1 Hurwitz (Lyapunov). The
  //! stability argument of seed 001 §3 needs exactly this pair, so a table must carry every digit
  //! (hex floats, or 17 significant digits for double, 9 for float), as design_gains writes it.
  //! In float, a pair whose P has a condition number near 1/ε (~1e7: poles spread over several
  //! decades) can fail the positive-definiteness of −(A_1ᵀP + PA_1): rounded to float it no
  //! longer proves stability, and the law is refused (measured: 31 of 2,000 random designs with
  //! poles from 1e-3 to 1e2 rad/s; none in double).
  static constexpr S kLyapunovResidualUlps = S(64);

  HybridAdaptive(const Params& p, const HybridAdaptiveGains<S>& g) noexcept : p_(p) {
    const Mat<6, 6, S> A1 = double_integrator_closed_loop<3, S>(g.K);
    const Mat<6, 6, S> AtP = A1.transpose() * g.P;
    const Mat<6, 6, S> Q_closed = -(AtP + AtP.transpose());  // −(A_1ᵀP + PA_1), symmetric by construction
    const S scale = S(2) * A1.norm() * g.P.norm() + p_.Q_L.norm();
    bool ok = all_finite(g.K) && symmetric_positive_definite<6, S>(g.P) &&
              symmetric_positive_definite<6, S>(p_.Q_L) && symmetric_positive_definite<6, S>(Q_closed) &&
              (p_.Q_L - Q_closed).norm() <= kLyapunovResidualUlps * std::numeric_limits<S>::epsilon() * scale;
    ok = ok && valid(p_.nominal) && valid(p_.steering);
    J_n_ = p_.nominal.J_tr(Vec<M, S>::Zero());  // spec §A.3: J_n = J_tr(0), nominal geometry
    const Eigen::LLT<Mat3S> llt(J_n_);
    ok = ok && llt.info() == Eigen::Success;
    J_n_inv_ = llt.solve(Mat3S::Identity());
    K_ = g.K;
    P_ = g.P;
    B0tP_ = P_.template bottomRows<3>();  // B0ᵀP with B0 = [0; I3]
    P22_norm_ = P_.template bottomRightCorner<3, 3>().norm();  // ‖P22‖_F for the step gain
    proj_ = ProjectionParamsT<S>{p_.alpha_G, p_.beta_G, p_.delta_G};
    ok = ok && valid(proj_) && finite_nonnegative(p_.alpha_F) && finite_positive(p_.period_s) &&
         all_finite(p_.H_I_n) && all_finite(J_n_inv_) && finite_positive(p_.max_step_gain);
    status_ = ADCS_CHECK(ok, "HybridAdaptive: invalid parameters (poles or gains, Q_L, nominal geometry, "
                             "steering, alpha, beta, delta, period)")
                  ? Status::ok
                  : Status::invalid_parameter;
    reset();
  }

  //! Construction outcome: ok, or invalid_parameter when the poles are not finite, conjugate
  //! pairs in the open left half-plane (or the given gains fail the checks above); Q_L is not
  //! symmetric positive definite; the nominal geometry is invalid (VscmgGeometry: finite, J_s
  //! SPD, inertias and h_cw >= 0; it has no default) or J_n = J_tr(0) not SPD; the steering parameters are invalid; α_F < 0, α_G < 0,
  //! β_G <= 0, δ_G <= 0, T_c <= 0, λ_max <= 0 or any of them or H_I_n not finite. A refused law
  //! answers invalid_parameter from every step() with its failure command.
  Status status() const noexcept { return status_; }
  S period_s() const noexcept { return p_.period_s; }

  //! Estimates to their initial values Θ̂(0) = 0 (spec §A.5), counters and command to zero.
  void reset() noexcept {
    theta_F_.setZero();
    theta_c_.setZero();
    theta_w_.setZero();
    last_ = Output{};
    safeguard_count_ = 0;
  }

  //! Which of the M gimbals (bits 0..M−1) and N wheels (bits M..M+N−1) may be commanded, as
  //! reported by the caller's FDIR. A failed actuator gets exactly 0 from the next step on and
  //! the steering spreads v over the others (actuator/steering.hpp, steer_available); its Θ̂_G
  //! block stops adapting (its regressor is multiplied by u_k = 0). Also updates the held
  //! command, so a rejected step never re-sends a failed actuator. out_of_range (mask unchanged)
  //! for bits beyond M+N. Survives reset().
  [[nodiscard]] Status set_available(ActuatorMask mask) noexcept {
    if ((mask & ~all_actuators<L>()) != 0u) return Status::out_of_range;
    available_ = mask;
    for (int k = 0; k < M; ++k)
      if (((mask >> k) & 1u) == 0u) last_.gamma_dot_rad_s(k) = S(0);
    for (int k = 0; k < N; ++k)
      if (((mask >> (M + k)) & 1u) == 0u) last_.Omega_dot_rad_s2(k) = S(0);
    return Status::ok;
  }
  ActuatorMask available() const noexcept { return available_; }

  //! One control sample. Returns ok; ill_conditioned (singularity-robust steering used, e.g. the
  //! available actuators cannot span all three axes);
  //! constraint_violated (the discrete safeguard rescaled an estimate; counted);
  //! non_finite_input / singular / out_of_range / invalid_parameter / request_not_met (the
  //! steering cannot deliver the torque) with `out` = the failure command (zero gimbal rates and
  //! wheel accelerations, or the last good command under hold_last) and every estimate untouched.
  [[nodiscard]] Status step(const Input& in, Output& out, Diagnostics* diag = nullptr) noexcept {
    out = failure_command(p_.on_failure, last_, Output{});
    if (status_ != Status::ok) return status_;
    const MrpReferenceSampleT<S>& r = in.reference;
    if (!all_finite(in.state.sigma_BN) || !all_finite(in.state.omega_BN_B) || !all_finite(in.actuators.gamma_rad) ||
        !all_finite(in.actuators.Omega_rad_s) || !all_finite(r.sigma) || !all_finite(r.sigma_dot) ||
        !all_finite(r.sigma_ddot))
      return Status::non_finite_input;

    const Vec3S& sigma = in.state.sigma_BN;
    const Vec3S& w = in.state.omega_BN_B;
    // Steps 1-3: kinematics and error.
    const Mat3S G = mrp_G(sigma);
    const Vec3S sigma_dot = G * w;                                   // seed 001 eq. (6)
    Vec6S e;
    e << sigma - r.sigma, sigma_dot - r.sigma_dot;
    const Vec3S PBe = B0tP_ * e;                                     // B0ᵀ P e
    const Mat3S G_dot = mrp_G_dot(sigma, sigma_dot);
    const Mat3S GJ = G * J_n_inv_;                                   // G J_n⁻¹ = H*⁻¹G⁻ᵀ
    // Steps 4-5: drift and its momentum regressor.
    const Mat3S Y_F = -GJ * skew(w) * mrp_to_dcm(sigma);             // seed 001 eq. (16)
    const Vec3S F_n = G_dot * w + Y_F * p_.H_I_n;                    // seed 001 eq. (15)
    // Steps 6-8: X = G*n + Y_G Θ̂_G column by column (seed 001 eqs. (17)-(20)).
    const Vec<M, S> cos_g = in.actuators.gamma_rad.array().cos(), sin_g = in.actuators.gamma_rad.array().sin();  // once per step
    Mat<3, L, S> X;
    for (int i = 0; i < M; ++i) {
      const S c = cos_g(i), s = sin_g(i);
      const Vec3S t_n = c * p_.nominal.A_ct0.col(i) - s * p_.nominal.A_cs0.col(i);   // seed 001 eq. (3)
      const Vec3S dt = c * theta_c_.col(i).template head<3>() - s * theta_c_.col(i).template tail<3>();
      X.col(i) = -p_.nominal.h_cw(i) * (GJ * (t_n + dt));                            // seed 001 eq. (19)
    }
    for (int j = 0; j < N; ++j)
      X.col(M + j) = -p_.nominal.I_wws(j) * (GJ * (p_.nominal.A_ws.col(j) + theta_w_.col(j)));
    // Step 9: desired σ̈.
    const Vec3S v = -K_ * e - F_n - Y_F * theta_F_ + r.sigma_ddot;   // seed 001 eq. (24)
    // Step 10: right pseudo-inverse (LDLT of X Xᵀ), singularity-robust fallback.
    Vec<L, S> u;
    SteeringInfoT<S> sinfo;
    const Status steer_status = steer_available<L, S>(X, v, p_.steering, available_, u, &sinfo);
    if (diag) {
      diag->e = e;
      diag->X = X;
      diag->steering = sinfo;
    }
    if (!usable(steer_status)) return steer_status;
    if (!all_finite(u)) return Status::out_of_range;

    // Steps 11-13: adaptation over T_c (explicit Euler, or its normalized step); commit only
    // if everything is finite. Per-step loop gains λ = T α ‖Y‖² ‖P22‖ (adapt/normalized_step.hpp):
    // ‖Y_F‖², and ‖Y_Gk u_k‖² = (h_cw,i or I_ws,j)² ‖GJ‖² u_k² since [c I3, −s I3] is orthonormal.
    const S T = p_.period_s;
    S scale_F = S(1);
    Vec<L, S> scale_u = Vec<L, S>::Ones();  // per-block scale of the Θ_G steps
    if (p_.adaptation_step == AdaptationStep::normalized) {
      const S k = T * P22_norm_, GJ2 = GJ.squaredNorm(), lim = p_.max_step_gain;
      scale_F = normalized_step_scale(k * p_.alpha_F * Y_F.squaredNorm(), lim);
      for (int i = 0; i < M; ++i) {
        const S hu = p_.nominal.h_cw(i) * u(i);
        scale_u(i) = normalized_step_scale(k * p_.alpha_G * GJ2 * hu * hu, lim);
      }
      for (int j = 0; j < N; ++j) {
        const S Iu = p_.nominal.I_wws(j) * u(M + j);
        scale_u(M + j) = normalized_step_scale(k * p_.alpha_G * GJ2 * Iu * Iu, lim);
      }
    }
    const Vec3S theta_F_next = theta_F_ + (T * p_.alpha_F * scale_F) * (Y_F.transpose() * PBe);  // seed 001 eq. (25)
    Mat<6, M, S> theta_c_next;
    Mat<3, N, S> theta_w_next;
    int active_blocks = 0;
    bool safeguard = false;
    const Vec3S GJtPBe = GJ.transpose() * PBe;
    for (int i = 0; i < M; ++i) {
      const S h = p_.nominal.h_cw(i);
      Vec6S Phi;  // Y_cGiᵀ PBe u_i, Y_cGi = −h_cw,i GJ [c I3, −s I3]        seed 001 eqs. (19), (26)
      Phi << -h * cos_g(i) * GJtPBe, h * sin_g(i) * GJtPBe;
      Vec6S next;
      if (!update_block<6>(theta_c_.col(i), Phi * (u(i) * scale_u(i)), next, active_blocks, safeguard))
        return Status::out_of_range;
      theta_c_next.col(i) = next;
    }
    for (int j = 0; j < N; ++j) {
      const Vec3S Phi = (-p_.nominal.I_wws(j) * u(M + j) * scale_u(M + j)) * GJtPBe;  // Y_wGjᵀ PBe u, seed 001 eq. (20)
      Vec3S next;
      if (!update_block<3>(theta_w_.col(j), Phi, next, active_blocks, safeguard))
        return Status::out_of_range;
      theta_w_next.col(j) = next;
    }
    if (!all_finite(theta_F_next) || !all_finite(theta_c_next) || !all_finite(theta_w_next))
      return Status::out_of_range;

    theta_F_ = theta_F_next;
    theta_c_ = theta_c_next;
    theta_w_ = theta_w_next;
    if (safeguard) ++safeguard_count_;
    if (diag) {
      diag->projection_active_blocks = active_blocks;
      diag->theta_F_step_scale = scale_F;
    }
    last_ = Output::from_stacked(u);
    out = last_;  // step 14: the caller holds u over the period (ZOH)
    if (safeguard) return Status::constraint_violated;
    return steer_status;
  }

  // --- estimates and constants (read-only) ---
  const Vec3S& theta_F() const noexcept { return theta_F_; }      //!< [N m s] Θ̂_F = Ĥ_I^Δ
  Vec6S theta_cG(int i) const noexcept { return theta_c_.col(i); }  //!< [-] [Δt̂_i0; Δŝ_i0]
  Vec3S theta_wG(int j) const noexcept { return theta_w_.col(j); }  //!< [-] Δŝ_wj
  std::uint32_t safeguard_count() const noexcept { return safeguard_count_; }
  const Mat<3, 6, S>& K() const noexcept { return K_; }
  const Mat<6, 6, S>& P() const noexcept { return P_; }
  const Mat3S& J_n() const noexcept { return J_n_; }
  const Params& params() const noexcept { return p_; }

  //! Sets the estimates (oracle tests with the true Θ, warm starts). Rejects non-finite values
  //! and blocks outside the invariant ball ‖Θ̂_Gk‖² ≤ β + δ, leaving the estimates untouched.
  [[nodiscard]] Status set_estimates(const Vec3S& theta_F, const Mat<6, M, S>& theta_c,
                                     const Mat<3, N, S>& theta_w) noexcept {
    if (!all_finite(theta_F) || !all_finite(theta_c) || !all_finite(theta_w))
      return Status::non_finite_input;
    const S bound = p_.beta_G + p_.delta_G;
    if ((theta_c.colwise().squaredNorm().array() > bound).any() ||
        (theta_w.colwise().squaredNorm().array() > bound).any())
      return Status::out_of_range;
    theta_F_ = theta_F;
    theta_c_ = theta_c;
    theta_w_ = theta_w;
    return Status::ok;
  }

 private:
  //! design_hybrid_adaptive_gains on the parameters cast to double (a no-op for S = double),
  //! rounded to S; NaN gains (refused by the checks) when the design fails.
  static HybridAdaptiveGains<S> designed_gains(const Params& p) noexcept {
    HybridAdaptiveGains<double> g;
    (void)design_hybrid_adaptive_gains(p.poles, p.Q_L, g);
    return g.template cast<S>();
  }

  //! One Θ_G block over a control period: θ⁺ = θ + T Proj(θ, Φ) (seed 001 eq. (26), explicit Euler,
  //! spec §A.3 step 13), then the radial safeguard to β + δ. False on a projection failure.
  template <int K>
  bool update_block(const Vec<K, S>& theta, const Vec<K, S>& Phi, Vec<K, S>& next, int& active_blocks,
                    bool& safeguard) const noexcept {
    Vec<K, S> rate;
    bool active = false;
    if (smooth_projection<K, S>(theta, Phi, proj_, rate, &active) != Status::ok) return false;
    next = theta + p_.period_s * rate;
    safeguard = radial_safeguard<K, S>(next, p_.beta_G + p_.delta_G) || safeguard;
    active_blocks += active;
    return true;
  }

  Params p_;
  Mat<3, 6, S> K_ = Mat<3, 6, S>::Zero();
  Mat<6, 6, S> P_ = Mat<6, 6, S>::Zero();
  Mat<3, 6, S> B0tP_ = Mat<3, 6, S>::Zero();
  S P22_norm_ = S(0);
  Mat3S J_n_ = Mat3S::Identity();
  Mat3S J_n_inv_ = Mat3S::Identity();
  ProjectionParamsT<S> proj_{};
  Status status_ = Status::ok;

  Vec3S theta_F_ = Vec3S::Zero();
  Mat<6, M, S> theta_c_ = Mat<6, M, S>::Zero();
  Mat<3, N, S> theta_w_ = Mat<3, N, S>::Zero();
  Output last_{};
  std::uint32_t safeguard_count_ = 0;
  ActuatorMask available_ = all_actuators<L>();
};

ADCS_ASSERT_COMPONENT(HybridAdaptive<4, 3>);
ADCS_ASSERT_COMPONENT(HybridAdaptive<4, 3, float>);

}  // namespace adcs
