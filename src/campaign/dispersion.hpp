#pragma once
// Dispersions of any numeric parameter (issue 18): `--disperse KEY=EXPR` on a registered
// scenario or a vehicle file. The key is a declared parameter (a number, vector or matrix; a
// file's parameters by their dotted path, e.g. spacecraft.J_kgm2); EXPR is one of
//
//   normal(mu, sd)              every element ~ N(mu, sd²)                    (absolute)
//   uniform(a, b)               every element ~ U(a, b)
//   truncnormal(mu, sd, lo, hi) every element ~ N(mu, sd²) restricted to [lo, hi]
//   rel_normal(sd)              every element x ← x (1 + N(0, sd²))          (relative to nominal)
//   rel_uniform(a)              every element x ← x (1 + U(−a, a))
//   inertia(rel_sd, rot_sd_deg) a 3x3 inertia: principal moments each × (1 + N(0, rel_sd²)),
//                               principal axes turned by a small rotation, N(0, rot_sd²) per axis
//   axes(sd_deg)                each unit axis (a 3-vector, or each row of an N x 3 matrix) tilted
//                               by two perpendicular components ~ N(0, sd²) (tilt ~ Rayleigh(sd))
//
// Element-wise forms draw every element independently. A draw is a pure function of (seed0, run,
// key) (seeding.hpp). A drawn value that makes a parameter unphysical is NOT fixed: the run is
// recorded invalid with the reason (an inertia that is not symmetric positive definite or breaks
// the triangle inequality J_i + J_j >= J_k; for the scenario's own checks, its ParamError).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/params.hpp"

namespace adcs::sim::campaign {

struct Dispersion {
  enum class Form { normal, uniform, truncnormal, rel_normal, rel_uniform, inertia, axes };
  std::string key;
  Form form = Form::normal;
  std::vector<double> args;  //!< as written (degrees stay degrees here)
  std::string text;          //!< the expression as given, for the campaign's record
};

//! Parses "KEY=EXPR"; throws ParamError with a one-line reason (unknown form, wrong argument
//! count, sd < 0, a > b, an empty truncation interval, a non-finite argument).
Dispersion parse_dispersion(const std::string& key_equals_expr);

//! Checks a dispersion against its parameter (throws ParamError naming the key): the key is
//! declared, numeric, and fits the form (inertia: a 3x3 matrix; axes: a 3-vector or N x 3).
void check_dispersion(const Dispersion& d, const ParamSet& ps);

//! One drawn value, applied to a parameter set.
struct DrawnValue {
  std::string key;
  ParamKind kind = ParamKind::number;
  ParamValue value;
};

//! Draws `d` for run `run` of the campaign seeded `seed0` from the nominal value in `nominal`.
DrawnValue draw(const Dispersion& d, const ParamSet& nominal, std::uint64_t seed0, std::uint64_t run);

//! Why a drawn value of parameter `p` is unphysical, or nothing: every element finite; an
//! inertia (a 3x3 matrix in kg m^2, or dispersed with inertia()) symmetric positive definite with
//! J_i + J_j >= J_k for its principal moments; tilted axes non-zero.
std::optional<std::string> physical_problem(const Dispersion& d, const DrawnValue& v, const Param& p);

//! "KEY" for a number, "KEY[i]" for a vector element, "KEY[i][j]" for a matrix element: the
//! column names of the drawn values in the campaign table, in row-major order.
std::vector<std::string> element_names(const DrawnValue& v);
std::vector<double> element_values(const DrawnValue& v);

}  // namespace adcs::sim::campaign
