#pragma once
// The seed 004 plant of the spec's Table 2, discretised (spec §B.3), for the drag-free tests. Apart
// from drag_free_test_params.hpp so that the model tests do not compile the filters.
#include <gtest/gtest.h>

#include "adcs/plant/drag_free.hpp"

namespace adcs::test::drag_free {
// The names every drag-free test uses, brought in by its `using namespace adcs::test::drag_free`.
using adcs::Mat3;
using adcs::Status;
using adcs::Vec3;
using Ix = adcs::DragFreeIndex;

inline adcs::DragFreeDiscrete discrete(const adcs::DragFreeParams& p = {}) {
  adcs::DragFreeDiscrete d;
  EXPECT_EQ(adcs::drag_free_discretize(p, d), Status::ok);
  return d;
}

}  // namespace adcs::test::drag_free
