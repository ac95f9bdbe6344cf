#pragma once
// adcs/actuator: wheel torque allocation, CMG steering (incl. singularity escape), saturation, quantizers.
// A family umbrella: include it, or only the headers below you use (each one is self-contained
// and compiles alone; docs/USER-GUIDE.md "Including only what you use").
#include "adcs/actuator/limits.hpp"
#include "adcs/actuator/quantizer.hpp"
#include "adcs/actuator/rw_allocation.hpp"
#include "adcs/actuator/saturation.hpp"
#include "adcs/actuator/steering.hpp"
#include "adcs/actuator/vscmg_steering.hpp"
