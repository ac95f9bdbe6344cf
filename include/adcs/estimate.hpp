#pragma once
// adcs/estimate: estimators: error-state Kalman filters, saturated extended-state filter, fusion.
// A family umbrella: include it, or only the headers below you use (each one is self-contained
// and compiles alone; docs/USER-GUIDE.md "Including only what you use").
#include "adcs/estimate/drag_free_eskf.hpp"
#include "adcs/estimate/eskf.hpp"
#include "adcs/estimate/extended_state_covariance.hpp"
#include "adcs/estimate/fusion.hpp"
#include "adcs/estimate/partitioned_eskf.hpp"
#include "adcs/estimate/saturated_esf.hpp"
