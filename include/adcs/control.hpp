#pragma once
// adcs/control: every control law (MRP PD, hybrid adaptive VSCMG, PPC neural, ATC, SE(3) laws, ADRC, PID).
// A family umbrella: include it, or only the headers below you use (each one is self-contained
// and compiles alone; docs/USER-GUIDE.md "Including only what you use").
#include "adcs/control/adaptive_tracking.hpp"
#include "adcs/control/adrc.hpp"
#include "adcs/control/eso_adrc_attitude.hpp"
#include "adcs/control/euler_tracking_common.hpp"
#include "adcs/control/ftsmc_se3.hpp"
#include "adcs/control/hybrid_adaptive.hpp"
#include "adcs/control/mrp_pd.hpp"
#include "adcs/control/nonsingular_power.hpp"
#include "adcs/control/pid.hpp"
#include "adcs/control/ppc_neural.hpp"
#include "adcs/control/prescribed_time_se3.hpp"
#include "adcs/control/se3_tracking_error.hpp"
