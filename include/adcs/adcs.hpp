#pragma once
// Everything: every family umbrella (adcs/core.hpp ... adcs/reference.hpp). Convenient, but a
// translation unit that includes it compiles every law in the library (about 4x the time of the
// three headers a reaction-wheel loop needs); flight code should include its family or its headers.
#include "adcs/core.hpp"
#include "adcs/math.hpp"
#include "adcs/actuator.hpp"
#include "adcs/adapt.hpp"
#include "adcs/control.hpp"
#include "adcs/estimate.hpp"
#include "adcs/plant.hpp"
#include "adcs/reference.hpp"
