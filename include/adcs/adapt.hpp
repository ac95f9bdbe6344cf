#pragma once
// adcs/adapt: adaptation building blocks: projection, bound estimators, RBF networks, prescribed-performance transform.
// A family umbrella: include it, or only the headers below you use (each one is self-contained
// and compiles alone; docs/USER-GUIDE.md "Including only what you use").
#include "adcs/adapt/bound_estimator.hpp"
#include "adcs/adapt/normalized_step.hpp"
#include "adcs/adapt/ppc.hpp"
#include "adcs/adapt/projection.hpp"
#include "adcs/adapt/rbf_compensator.hpp"
#include "adcs/adapt/rbf_network.hpp"
