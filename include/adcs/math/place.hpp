#pragma once
// Gain from desired closed-loop eigenvalues for the block double integrator
//   x = [q; q_dot] (Axes each),  x_dot = A0 x + B0 a,  a = -K x,  A1 = A0 - B0 K,
//   A0 = [[0, I], [0, 0]],  B0 = [0; I]          (seed 001 eq. (14), §A.3)
// with one eigenvalue pair per axis, giving the diagonal K = [Kp Kd], s^2 + kd s + kp per axis.
// seed 001 §A.4 #22: K is not unique for this multi-input system; the per-axis diagonal choice is
// reproducible and gives P a closed form.
#include <array>
#include <complex>

#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"

namespace adcs {

template <int Axes>
using AxisPoles = std::array<std::array<std::complex<double>, 2>, Axes>;

//! K (Axes x 2Axes) placing axis i's eigenvalues at poles[i]. Each pair must be real or a
//! complex-conjugate pair (else out_of_range, K untouched).
template <int Axes>
Status place_double_integrator(const AxisPoles<Axes>& poles, Mat<Axes, 2 * Axes>& K) noexcept {
  Vec<Axes> kp, kd;
  for (int i = 0; i < Axes; ++i) {
    const std::complex<double> a = poles[i][0], b = poles[i][1];
    if (!std::isfinite(a.real()) || !std::isfinite(a.imag()) || !std::isfinite(b.real()) ||
        !std::isfinite(b.imag()))
      return Status::non_finite_input;
    const std::complex<double> sum = a + b, prod = a * b;
    const double tol = 1e-12 * (1.0 + std::abs(a) + std::abs(b));
    // s^2 - (a+b) s + a b must have real coefficients.
    if (std::abs(sum.imag()) > tol || std::abs(prod.imag()) > tol * (1.0 + std::abs(prod)))
      return Status::out_of_range;
    kp(i) = prod.real();
    kd(i) = -sum.real();
  }
  K.setZero();
  K.template leftCols<Axes>().diagonal() = kp;
  K.template rightCols<Axes>().diagonal() = kd;
  return Status::ok;
}

//! A1 = A0 - B0 K for the block double integrator (S explicit: `<3, float>`).
template <int Axes, class S = double>
Mat<2 * Axes, 2 * Axes, S> double_integrator_closed_loop(const identity_t<Mat<Axes, 2 * Axes, S>>& K) noexcept {
  Mat<2 * Axes, 2 * Axes, S> A1 = Mat<2 * Axes, 2 * Axes, S>::Zero();
  A1.template topRightCorner<Axes, Axes>().setIdentity();
  A1.template bottomRows<Axes>() = -K;
  return A1;
}

}  // namespace adcs
