#pragma once
// adcs/core: status codes, failure policy and hook, scalar/vector types.
// A family umbrella: include it, or only the headers below you use (each one is self-contained
// and compiles alone; docs/USER-GUIDE.md "Including only what you use").
#include "adcs/core/component.hpp"
#include "adcs/core/failure_hook.hpp"
#include "adcs/core/failure_policy.hpp"
#include "adcs/core/plant.hpp"
#include "adcs/core/signals.hpp"
#include "adcs/core/status.hpp"
#include "adcs/core/types.hpp"
#include "adcs/core/validation.hpp"
