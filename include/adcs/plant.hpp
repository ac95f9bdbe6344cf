#pragma once
// adcs/plant: plant models for simulation and for the laws that use them (rigid body + wheels, VSCMG, flexible, SE(3), drag-free) and ready-made configurations.
// A family umbrella: include it, or only the headers below you use (each one is self-contained
// and compiles alone; docs/USER-GUIDE.md "Including only what you use").
#include "adcs/plant/drag_free.hpp"
#include "adcs/plant/drag_free_plant.hpp"
#include "adcs/plant/flexible_configurations.hpp"
#include "adcs/plant/flexible_spacecraft.hpp"
#include "adcs/plant/orbit_environment.hpp"
#include "adcs/plant/rigid_body_rw.hpp"
#include "adcs/plant/se3_spacecraft.hpp"
#include "adcs/plant/se3_spacecraft_plant.hpp"
#include "adcs/plant/vscmg_cluster.hpp"
#include "adcs/plant/vscmg_configurations.hpp"
