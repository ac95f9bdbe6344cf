#pragma once
// Seed 004 filter parameters shared by the drag-free estimator tests (test_drag_free_eskf.cpp,
// test_drag_free_filters.cpp): Algorithms 1 and 2 set up as the dragfree-adrc scenario sets them
// up (spec §B.8), on the plant of drag_free_test_model.hpp.
#include <gtest/gtest.h>

#include <cmath>

#include "adcs/estimate/drag_free_eskf.hpp"
#include "adcs/estimate/saturated_esf.hpp"
#include "adcs/plant/drag_free.hpp"
#include "drag_free_test_model.hpp"

namespace adcs::test::drag_free {

inline adcs::DragFreeEskf::Params eskf_params(const adcs::DragFreeDiscrete& d) {
  const adcs::DragFreeParams p;
  const adcs::DragFreeNoise n = adcs::drag_free_noise(p);
  adcs::DragFreeEskf::Params e;
  e.A_d = d.A_d;
  e.B_d = d.B_d;
  e.B_e = d.B_e;
  e.C_d = d.C_d;
  const double q = std::pow(7.7e-3 * 1.2e-3 * 0.1, 2);  // spec §B.8: 8.538e-13
  e.q << Vec3::Constant(q), Vec3::Constant(q), Vec3::Zero();
  adcs::Vec<9> s;
  s << Vec3::Constant(n.sigma_T_sc * n.sigma_T_sc), Vec3::Constant(n.sigma_F_sc * n.sigma_F_sc),
      Vec3::Constant(n.sigma_T_tm * n.sigma_T_tm);
  e.S = s.asDiagonal();
  e.R = n.sigma_pos * n.sigma_pos * adcs::Mat<9, 9>::Identity();
  e.period_s = p.period_s;  // the period A_d, B_d were discretised at (discrete() uses the defaults too)
  return e;
}

inline adcs::SaturatedEsfParams esf_params(int axis, bool saturating = true) {
  const adcs::DragFreeParams p;
  const adcs::DragFreeNoise n = adcs::drag_free_noise(p);
  adcs::DragFreeAxisModel m;
  EXPECT_EQ(adcs::drag_free_axis_model(p, axis, m), Status::ok);
  adcs::SaturatedEsfParams e;
  e.A_d = m.A_d;
  e.B_d = m.B_d;
  e.B_e = m.B_e;
  e.C = m.C;
  e.D = m.D;
  e.q = std::pow(7.7e-3 * 1.2e-3 * 0.1, 2);
  e.S = n.sigma_F_sc * n.sigma_F_sc;
  e.R_a = n.sigma_acc * n.sigma_acc;
  e.period_s = p.period_s;  // the period the axis model was discretised at
  if (saturating) {
    e.y_min = p.accel_min;
    e.y_max = p.accel_max;
  }
  return e;
}
}  // namespace adcs::test::drag_free
