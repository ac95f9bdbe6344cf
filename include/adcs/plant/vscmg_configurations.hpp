#pragma once
// Ready-made VSCMG cluster configurations (data, not the only option):
//   pyramid_4cmg_3rw_nominal()  nominal 4-CMG Wie pyramid + 3 body-aligned wheels, spec A.5
//   deviation_set_D1()          fixed installation deviations D1, spec A.2.3
// and builders for a user's own cluster:
//   set_cmg_pyramid(skew, h, g) M ≥ 3 CMGs in a pyramid of any skew angle and rotor momentum
//   wheel_pyramid_axes(elev, A) N ≥ 3 wheel spin axes in a pyramid of any elevation
// A-REF truth geometry = apply_deviation(pyramid_4cmg_3rw_nominal(), deviation_set_D1()).
#include <cmath>

#include "adcs/core/status.hpp"
#include "adcs/plant/vscmg_cluster.hpp"

namespace adcs {

//! M single-gimbal CMGs in a pyramid (Wie's pyramid for M = 4, generalised): CMG i sits on the
//! face at azimuth α_i = 2π i / M, its gimbal axis g_i = (sin β cos α_i, sin β sin α_i, cos β) makes
//! the skew angle β with the pyramid's z axis (β = arccos(1/√3) = 54.74° gives four CMGs a
//! near-spherical momentum envelope), its rotor spin axis at γ = 0 is s_i0 = (−sin α_i, cos α_i, 0)
//! (zero total momentum at γ = 0) and t_i0 = g_i × s_i0. Every rotor has momentum h_cw_Nms.
//! Sets A_cg, A_cs0, A_ct0 and h_cw; wheels, inertias and J_s are the caller's.
//! invalid_parameter (g untouched) unless 0 < β < π/2 and h_cw_Nms > 0, both finite.
template <int M, int N>
[[nodiscard]] inline Status set_cmg_pyramid(double skew_rad, double h_cw_Nms, VscmgGeometry<M, N>& g) noexcept {
  static_assert(M >= 3, "a CMG pyramid needs at least 3 CMGs to span three axes");
  if (!(skew_rad > 0.0 && skew_rad < 0.5 * kPiRad) || !(h_cw_Nms > 0.0) || !std::isfinite(h_cw_Nms))
    return Status::invalid_parameter;
  const double sb = std::sin(skew_rad), cb = std::cos(skew_rad);
  for (int i = 0; i < M; ++i) {
    const double a = 2.0 * kPiRad * i / M;
    g.A_cg.col(i) = Vec3(sb * std::cos(a), sb * std::sin(a), cb);
    g.A_cs0.col(i) = Vec3(-std::sin(a), std::cos(a), 0.0);
    g.A_ct0.col(i) = Vec3(g.A_cg.col(i)).cross(Vec3(g.A_cs0.col(i)));
  }
  g.h_cw.setConstant(h_cw_Nms);
  return Status::ok;
}

//! N ≥ 3 reaction-wheel spin axes in a pyramid: wheel j at azimuth α_j = 2π j / N, elevated by
//! e above the x-y plane: s_wj = (cos e cos α_j, cos e sin α_j, sin e) (unit columns).
//! invalid_parameter (A_ws untouched) unless 0 < e < π/2 (e = 0 or π/2 cannot span 3 axes).
template <int N>
[[nodiscard]] inline Status wheel_pyramid_axes(double elevation_rad, Mat<3, N>& A_ws) noexcept {
  static_assert(N >= 3, "a wheel pyramid needs at least 3 wheels to span three axes");
  if (!(elevation_rad > 0.0 && elevation_rad < 0.5 * kPiRad)) return Status::invalid_parameter;
  const double ce = std::cos(elevation_rad), se = std::sin(elevation_rad);
  for (int j = 0; j < N; ++j) {
    const double a = 2.0 * kPiRad * j / N;
    A_ws.col(j) = Vec3(ce * std::cos(a), ce * std::sin(a), se);
  }
  return Status::ok;
}

//! Nominal 4 SGCMG pyramid + 3 orthogonal wheels of seed 001 (paper gives no numbers; every
//! value below is a spec A.5 assumption).
inline VscmgGeometry<4, 3> pyramid_4cmg_3rw_nominal() noexcept {
  // assumed (spec A.5): skew beta_p = arccos(1/sqrt(3)) = 54.7356 deg, near-spherical envelope
  const double cb = 1.0 / std::sqrt(3.0);        //!< [-] cos(beta_p) = 0.57735027
  const double sb = std::sqrt(2.0 / 3.0);        //!< [-] sin(beta_p) = 0.81649658
  VscmgGeometry<4, 3> g;
  // assumed (spec A.5): standard Wie pyramid; g x s0 = t0, zero CMG momentum at gamma = 0
  g.A_cg << sb, 0.0, -sb, 0.0,  //
      0.0, sb, 0.0, -sb,        //
      cb, cb, cb, cb;
  g.A_cs0 << 0.0, -1.0, 0.0, 1.0,  //
      1.0, 0.0, -1.0, 0.0,         //
      0.0, 0.0, 0.0, 0.0;
  g.A_ct0 << -cb, 0.0, cb, 0.0,  //
      0.0, -cb, 0.0, cb,         //
      sb, sb, sb, sb;
  // assumed (spec A.5): "3 个正装飞轮" = wheels aligned with the body axes
  g.A_ws = Mat3::Identity();
  // assumed (spec A.5): small agile satellite; alpha_F = 1e7 only usable for J ~ 1e2 kg m^2
  g.J_s = Vec3(120.0, 100.0, 80.0).asDiagonal();
  // assumed (spec A.5): body momentum needed <~ 4 N m s, keeps |gamma| <= 0.28 rad
  g.h_cw = Vec<4>::Constant(10.0);
  // assumed (spec A.5): gimbal+rotor inertias small vs J_s; enter only the truth plant
  g.I_cs = Vec<4>::Constant(0.012);
  g.I_ct = Vec<4>::Constant(0.006);
  g.I_cg = Vec<4>::Constant(0.01);
  // assumed (spec A.5): typical small reaction wheel spin inertia
  g.I_wws = Vec3::Constant(0.02);
  return g;
}

//! Deviation set D1 (spec A.2.3, ASSUMPTION): drawn once from U[-0.05, 0.05], rounded to 4
//! decimals. Rows are body x, y, z; columns CMG 1..4 or wheel 1..3. Mode A (unnormalised).
inline VscmgDeviation<4, 3> deviation_set_D1() noexcept {
  VscmgDeviation<4, 3> d;
  d.dA_cs0 << -0.0295, 0.0473, -0.0181, 0.0029,  //
      -0.0343, 0.0225, -0.0112, -0.0104,         //
      0.0057, -0.0198, 0.0491, -0.0355;
  d.dA_ct0 << -0.0233, 0.0257, 0.0296, 0.0498,  //
      0.0445, -0.0401, -0.0476, 0.0478,         //
      0.0041, -0.0449, -0.0158, 0.0424;
  d.dA_ws << -0.0253, 0.0057, -0.0345,  //
      0.0060, 0.0195, -0.0091,          //
      0.0372, 0.0033, -0.0355;
  d.dA_cg << 0.0284, -0.0217, -0.0132, 0.0364,  //
      -0.0308, 0.0404, 0.0422, -0.0498,         //
      0.0233, 0.0354, -0.0175, -0.0484;
  return d;
}

//! A-REF parameters: truth = nominal + D1, nominal = pyramid_4cmg_3rw_nominal().   spec A.5
inline VscmgParams<4, 3> vscmg_params_A_REF() noexcept {
  VscmgParams<4, 3> p;
  p.nominal = pyramid_4cmg_3rw_nominal();
  p.truth = apply_deviation(p.nominal, deviation_set_D1());
  return p;
}

}  // namespace adcs
