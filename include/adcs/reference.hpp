#pragma once
// adcs/reference: reference generators (sinusoidal Euler angles and rates).
// A family umbrella: include it, or only the headers below you use (each one is self-contained
// and compiles alone; docs/USER-GUIDE.md "Including only what you use").
#include "adcs/reference/sinusoidal_euler.hpp"
#include "adcs/reference/sinusoidal_rate.hpp"
