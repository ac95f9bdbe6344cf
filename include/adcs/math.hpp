#pragma once
// adcs/math: rotations (MRP, quaternions, Euler angles, SO(3)/SE(3)), pseudo-inverses, matrix exponential, Lyapunov, pole placement.
// A family umbrella: include it, or only the headers below you use (each one is self-contained
// and compiles alone; docs/USER-GUIDE.md "Including only what you use").
#include "adcs/math/euler.hpp"
#include "adcs/math/euler_dynamics.hpp"
#include "adcs/math/expm.hpp"
#include "adcs/math/lyapunov.hpp"
#include "adcs/math/mrp.hpp"
#include "adcs/math/pinv.hpp"
#include "adcs/math/place.hpp"
#include "adcs/math/quaternion.hpp"
#include "adcs/math/se3.hpp"
#include "adcs/math/so3.hpp"
#include "adcs/math/truncated_normal.hpp"
