#pragma once
// Signed powers and the C¹ non-singular switching function of the seed 003 backstepping law
// (§2.3 seed 003 eqs. (29)-(35), spec §A.5 "Per-channel functions" [R]; also the FTSMC surface, §A.6):
//
//   sig^a(z) = sign(z)|z|^a
//   S(z;ε)   = sig^{1−p}(z)                  |z| > ε
//            = l1 z + l2 sign(z) z²          |z| ≤ ε,   l1 = (1+p)ε^{−p},  l2 = −p ε^{−1−p}
//   S'(z;ε)  = (1−p)|z|^{−p}                 |z| > ε
//            = l1 + 2 l2 |z|                 |z| ≤ ε
//
// sig^{1−p} alone has an infinite slope at 0, so its time derivative (needed in α̇) blows up as
// z → 0; the quadratic patch matches value and slope at |z| = ε (S(ε) = ε^{1−p},
// S'(ε) = (1−p)ε^{−p}), so S is C¹ and S'(0) = l1 is finite. S is odd and S' even, exactly:
// both are evaluated on |z| and the sign restored.
#include <cmath>

#include "adcs/core/failure_hook.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

namespace detail {
//! |x|^a for x ≥ 0. For a = 0.5, 1, 2 the cheap forms sqrt(x), x, x·x are the correctly rounded
//! |x|^a (IEEE 754), the result an exact pow gives. For a = 1.5 and −0.5 (seed 003's sig^{1+p}
//! and S' = (1−p)|z|^{−p} at p = 0.5) x·sqrt(x) and 1/sqrt(x) round twice (≤ 1 ulp more than a
//! correctly rounded pow) but are IEEE-exact operations: bit-identical on the host and on the
//! Cortex-M7, where newlib's pow differs from glibc's in the last ulp, and ~20 instead of several
//! hundred target instructions (issue 7 budget; 24 pow calls per BsPdTC step before).
//! Other exponents stay with std::pow (powf in float).
template <class S>
inline S abs_pow(S x, identity_t<S> a) noexcept {
  if (a == S(0.5)) return std::sqrt(x);  // p = 0.5 of seed 003 (spec §A.8): sig^{1−p}
  if (a == S(1)) return x;
  if (a == S(2)) return x * x;
  if (a == S(1.5)) return x * std::sqrt(x);   // sig^{1+p}, p = 0.5
  if (a == S(-0.5)) return S(1) / std::sqrt(x);  // S'(z) factor |z|^{−p}, p = 0.5
  return std::pow(x, a);
}
}  // namespace detail

//! sig^a(z) = sign(z)|z|^a with sign(0) = 0, so sig^a(0) = 0 for every a (a > 0 expected).
template <class S>
inline S sig(S z, identity_t<S> a) noexcept {
  if (z == S(0)) return S(0);
  return std::copysign(detail::abs_pow(std::fabs(z), a), z);
}

//! sig^a applied componentwise.
template <int M, class S>
Vec<M, S> sig(const Vec<M, S>& z, identity_t<S> a) noexcept {
  Vec<M, S> out;
  for (int i = 0; i < M; ++i) out(i) = sig(z(i), a);
  return out;
}

//! Scalar S (issue 19): the float instance serves the float SE(3) laws.
template <class S = double>
struct NonsingularPowerParamsT {
  S p = S(0.5);     //!< [-] power p ∈ (0,1); S ~ sig^{1−p} outside the patch (spec §A.8 [A])
  S eps = S(0.01);  //!< [z units: rad, m, rad/s, m/s] patch half-width ε > 0 (spec §A.8 [A])
};
using NonsingularPowerParams = NonsingularPowerParamsT<double>;

//! True when 0 < p < 1 and ε > 0 (both finite), the domain where S is C¹ and l1, l2 are finite.
template <class S>
inline bool valid(const NonsingularPowerParamsT<S>& q) noexcept {
  return std::isfinite(q.p) && std::isfinite(q.eps) && q.p > S(0) && q.p < S(1) && q.eps > S(0);
}

//! S(z;ε) and S'(z;ε) for one (p, ε), with l1, l2 computed once at construction. With invalid
//! parameters status() is invalid_parameter and value()/derivative() return 0 (a controller
//! term that vanishes instead of a non-finite one); check status() after construction. A
//! non-finite z gives a non-finite result: callers check their inputs.
template <class S = double>
class NonsingularPowerT {
 public:
  using Params = NonsingularPowerParamsT<S>;
  explicit NonsingularPowerT(const Params& q = Params{}) noexcept : q_(q) {
    if (!ADCS_CHECK(valid(q_), "NonsingularPower: need p in (0,1), eps > 0")) {
      status_ = Status::invalid_parameter;
      return;
    }
    one_minus_p_ = S(1) - q_.p;
    l1_ = (S(1) + q_.p) * std::pow(q_.eps, -q_.p);       // spec §A.5
    l2_ = -q_.p * std::pow(q_.eps, S(-1) - q_.p);        // spec §A.5
  }

  Status status() const noexcept { return status_; }
  const Params& params() const noexcept { return q_; }
  S l1() const noexcept { return l1_; }  //!< [z^{−p}] slope of S at 0, S'(0)
  S l2() const noexcept { return l2_; }  //!< [z^{−1−p}] quadratic coefficient of the patch

  //! S(z;ε). The patch is written z (l1 + l2|z|) = l1 z + l2 sign(z) z².
  S value(S z) const noexcept {
    if (status_ != Status::ok) return S(0);
    const S a = std::fabs(z);
    if (a > q_.eps) return std::copysign(detail::abs_pow(a, one_minus_p_), z);
    return z * (l1_ + l2_ * a);
  }

  //! S'(z;ε) = dS/dz.
  S derivative(S z) const noexcept {
    if (status_ != Status::ok) return S(0);
    const S a = std::fabs(z);
    if (a > q_.eps) return one_minus_p_ * detail::abs_pow(a, -q_.p);
    return l1_ + S(2) * l2_ * a;
  }

  //! S applied componentwise.
  template <int M>
  Vec<M, S> value(const Vec<M, S>& z) const noexcept {
    Vec<M, S> out;
    for (int i = 0; i < M; ++i) out(i) = value(z(i));
    return out;
  }

  //! S' applied componentwise (the diagonal of ∂S(z)/∂z).
  template <int M>
  Vec<M, S> derivative(const Vec<M, S>& z) const noexcept {
    Vec<M, S> out;
    for (int i = 0; i < M; ++i) out(i) = derivative(z(i));
    return out;
  }

 private:
  Params q_;
  S one_minus_p_ = S(1);
  S l1_ = S(0);
  S l2_ = S(0);
  Status status_ = Status::ok;
};
using NonsingularPower = NonsingularPowerT<double>;

}  // namespace adcs
