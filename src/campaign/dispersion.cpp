#include "campaign/dispersion.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "adcs/core/types.hpp"
#include "campaign/seeding.hpp"

namespace adcs::sim::campaign {
namespace ADCS_UNITY_ID {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct FormInfo {
  const char* name;
  Dispersion::Form form;
  std::size_t args;
};
constexpr FormInfo kForms[] = {
    {"normal", Dispersion::Form::normal, 2},           {"uniform", Dispersion::Form::uniform, 2},
    {"truncnormal", Dispersion::Form::truncnormal, 4}, {"rel_normal", Dispersion::Form::rel_normal, 1},
    {"rel_uniform", Dispersion::Form::rel_uniform, 1}, {"inertia", Dispersion::Form::inertia, 2},
    {"axes", Dispersion::Form::axes, 1},
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

//! Standard normal CDF (ground code: only to refuse a truncation interval with almost no mass).
double phi(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

//! A small rotation from the rotation vector a (|a| << 1) by the Cayley transform
//! R = (I - [a/2]x)^-1 (I + [a/2]x): exactly orthogonal, rotation angle 2 atan(|a|/2) = |a| + O(|a|^3),
//! and only +, -, *, / (the same bits on every machine, unlike sin/cos).
Mat3 small_rotation(const Vec3& a) {
  Mat3 S;
  const Vec3 h = 0.5 * a;
  S << 0.0, -h(2), h(1), h(2), 0.0, -h(0), -h(1), h(0), 0.0;
  const Mat3 I = Mat3::Identity();
  return (I - S).partialPivLu().solve(I + S);
}

//! Two unit vectors perpendicular to the unit vector n (and to each other).
void perpendicular_basis(const Vec3& n, Vec3& e1, Vec3& e2) {
  int k = 0;  // the axis least aligned with n
  for (int i = 1; i < 3; ++i)
    if (std::abs(n(i)) < std::abs(n(k))) k = i;
  e1 = n.cross(Vec3::Unit(k)).normalized();
  e2 = n.cross(e1);
}

double draw_element(const Dispersion& d, Rng& rng, double nominal) {
  const std::vector<double>& a = d.args;
  switch (d.form) {
    case Dispersion::Form::normal: return rng.normal(a[0], a[1]);
    case Dispersion::Form::uniform: return rng.uniform(a[0], a[1]);
    case Dispersion::Form::truncnormal:
      for (;;) {  // rejection: parse_dispersion refused intervals with less than 1e-3 of the mass
        const double x = rng.normal(a[0], a[1]);
        if (x >= a[2] && x <= a[3]) return x;
      }
    case Dispersion::Form::rel_normal: return nominal * (1.0 + rng.normal(0.0, a[0]));
    case Dispersion::Form::rel_uniform: return nominal * (1.0 + rng.uniform(-a[0], a[0]));
    default: return nominal;
  }
}

Mat3 to_mat3(const std::vector<std::vector<double>>& m) {
  Mat3 J;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) J(i, j) = m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  return J;
}

}  // namespace
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)

Dispersion parse_dispersion(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw ParamError("--disperse '" + text + "': expected KEY=EXPR, e.g. J_kgm2=rel_normal(0.05)");
  Dispersion d;
  d.key = trim(text.substr(0, eq));
  d.text = trim(text.substr(eq + 1));
  if (d.key.empty()) throw ParamError("--disperse '" + text + "': the key is empty");
  const auto open = d.text.find('('), close = d.text.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open || trim(d.text.substr(close + 1)) != "")
    throw ParamError("--disperse " + d.key + ": '" + d.text + "' is not FORM(args), e.g. normal(0, 0.1)");
  const std::string name = trim(d.text.substr(0, open));
  const FormInfo* info = nullptr;
  for (const auto& fi : kForms)
    if (name == fi.name) info = &fi;
  if (!info)
    throw ParamError("--disperse " + d.key + ": unknown form '" + name +
                     "' (normal, uniform, truncnormal, rel_normal, rel_uniform, inertia, axes)");
  d.form = info->form;
  std::stringstream args(d.text.substr(open + 1, close - open - 1));
  std::string item;
  while (std::getline(args, item, ',')) {
    const std::string t = trim(item);
    std::size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(t, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (t.empty() || used != t.size() || !std::isfinite(x))
      throw ParamError("--disperse " + d.key + ": argument '" + t + "' of " + name + " is not a finite number");
    d.args.push_back(x);
  }
  if (d.args.size() != info->args)
    throw ParamError("--disperse " + d.key + ": " + name + " takes " + std::to_string(info->args) + " argument" +
                     (info->args > 1 ? "s" : "") + ", got " + std::to_string(d.args.size()));
  const std::vector<double>& a = d.args;
  const auto refuse = [&](const std::string& why) { throw ParamError("--disperse " + d.key + ": " + d.text + ": " + why); };
  switch (d.form) {
    case Dispersion::Form::normal:
    case Dispersion::Form::rel_normal:
      if (a.back() < 0.0) refuse("the standard deviation must be >= 0");
      break;
    case Dispersion::Form::uniform:
      if (!(a[0] <= a[1])) refuse("needs a <= b");
      break;
    case Dispersion::Form::rel_uniform:
      if (a[0] < 0.0) refuse("the half-width must be >= 0");
      break;
    case Dispersion::Form::truncnormal:
      if (!(a[1] > 0.0)) refuse("the standard deviation must be > 0");
      if (!(a[2] < a[3])) refuse("needs lo < hi");
      if (phi((a[3] - a[0]) / a[1]) - phi((a[2] - a[0]) / a[1]) < 1e-3)
        refuse("[lo, hi] holds less than 0.1 % of the normal's mass");
      break;
    case Dispersion::Form::inertia:
      if (a[0] < 0.0 || a[1] < 0.0) refuse("both standard deviations must be >= 0");
      break;
    case Dispersion::Form::axes:
      if (a[0] < 0.0) refuse("the standard deviation must be >= 0");
      break;
  }
  return d;
}

void check_dispersion(const Dispersion& d, const ParamSet& ps) {
  if (!ps.has(d.key)) {
    std::string msg = "--disperse: unknown parameter '" + d.key + "'";
    const auto near = ps.suggestions(d.key);
    if (!near.empty()) {
      msg += " (did you mean ";
      for (std::size_t i = 0; i < near.size(); ++i) msg += (i ? ", " : "") + near[i];
      msg += "?)";
    }
    throw ParamError(msg);
  }
  const Param& p = ps.at(d.key);
  if (p.kind == ParamKind::name) throw ParamError("--disperse " + d.key + ": a name parameter cannot be dispersed");
  if (d.form == Dispersion::Form::inertia && !(p.kind == ParamKind::matrix && p.rows == 3 && p.cols == 3))
    throw ParamError("--disperse " + d.key + ": inertia(...) needs a 3x3 matrix parameter");
  if (d.form == Dispersion::Form::axes &&
      !((p.kind == ParamKind::vector && p.size == 3) || (p.kind == ParamKind::matrix && p.cols == 3)))
    throw ParamError("--disperse " + d.key + ": axes(...) needs a 3-vector or an N x 3 matrix (one axis per row)");
}

DrawnValue draw(const Dispersion& d, const ParamSet& nominal, std::uint64_t seed0, std::uint64_t run) {
  const Param& p = nominal.at(d.key);
  DrawnValue v{d.key, p.kind, p.value};
  Rng rng = stream(seed0, run, d.key);
  if (d.form == Dispersion::Form::inertia) {
    // J = V diag(λ) Vᵀ; λ_i (1 + N(0, rel_sd²)); V ← R V with R a rotation of N(0, rot_sd²) per axis.
    const Mat3 J0 = to_mat3(p.value.matrix);
    Eigen::SelfAdjointEigenSolver<Mat3> es(0.5 * (J0 + J0.transpose()));
    Vec3 lambda = es.eigenvalues();
    for (int i = 0; i < 3; ++i) lambda(i) *= 1.0 + rng.normal(0.0, d.args[0]);
    Vec3 rot;
    for (int i = 0; i < 3; ++i) rot(i) = rng.normal(0.0, d.args[1] * kDeg);
    const Mat3 V = small_rotation(rot) * es.eigenvectors();
    Mat3 J = V * lambda.asDiagonal() * V.transpose();
    for (int i = 0; i < 3; ++i)  // symmetric to the last bit (a + b = b + a exactly)
      for (int j = i + 1; j < 3; ++j) J(i, j) = J(j, i) = 0.5 * (J(i, j) + J(j, i));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) v.value.matrix[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = J(i, j);
    return v;
  }
  if (d.form == Dispersion::Form::axes) {
    auto tilt = [&](std::vector<double>& axis) {
      const Vec3 a(axis[0], axis[1], axis[2]);
      const double n = a.norm();
      if (!(n > 0.0)) return;  // physical_problem() reports it
      Vec3 e1, e2;
      perpendicular_basis(a / n, e1, e2);
      const double t1 = rng.normal(0.0, d.args[0] * kDeg), t2 = rng.normal(0.0, d.args[0] * kDeg);
      const Vec3 b = small_rotation(t1 * e1 + t2 * e2) * a;  // |b| = |a|: a unit axis stays unit
      for (int i = 0; i < 3; ++i) axis[static_cast<std::size_t>(i)] = b(i);
    };
    if (p.kind == ParamKind::vector) tilt(v.value.vector);
    else
      for (auto& row : v.value.matrix) tilt(row);
    return v;
  }
  switch (p.kind) {  // element-wise, row-major
    case ParamKind::number: v.value.number = draw_element(d, rng, p.value.number); break;
    case ParamKind::vector:
      for (double& x : v.value.vector) x = draw_element(d, rng, x);
      break;
    case ParamKind::matrix:
      for (auto& row : v.value.matrix)
        for (double& x : row) x = draw_element(d, rng, x);
      break;
    case ParamKind::name: break;
  }
  return v;
}

std::optional<std::string> physical_problem(const Dispersion& d, const DrawnValue& v, const Param& p) {
  for (double x : element_values(v))
    if (!std::isfinite(x)) return d.key + ": drawn value not finite";
  if (v.kind == ParamKind::matrix && v.value.matrix.size() == 3 && v.value.matrix.front().size() == 3 &&
      (d.form == Dispersion::Form::inertia || p.unit == "kg m^2")) {
    // An inertia: a 3x3 matrix in kg m^2, or one dispersed as an inertia.
    const Mat3 J = to_mat3(v.value.matrix);
    const double scale = J.cwiseAbs().maxCoeff();
    if (!((J - J.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale))
      return d.key + ": drawn inertia is not symmetric (disperse it with inertia(rel_sd, rot_sd_deg))";
    const Vec3 l = Eigen::SelfAdjointEigenSolver<Mat3>(J).eigenvalues();
    if (!(l(0) > 0.0)) return d.key + ": drawn inertia is not positive definite (smallest principal moment " +
                              format_number(l(0)) + ")";
    if (!(l(0) + l(1) >= l(2))) return d.key + ": drawn inertia breaks the triangle inequality (" +
                                       format_number(l(0)) + " + " + format_number(l(1)) + " < " + format_number(l(2)) + ")";
  }
  if (d.form == Dispersion::Form::axes) {
    const auto rows = v.kind == ParamKind::vector ? std::vector<std::vector<double>>{v.value.vector} : v.value.matrix;
    for (const auto& r : rows)
      if (!(Vec3(r[0], r[1], r[2]).norm() > 0.0)) return d.key + ": a zero axis cannot be tilted";
  }
  return std::nullopt;
}

std::vector<std::string> element_names(const DrawnValue& v) {
  std::vector<std::string> n;
  switch (v.kind) {
    case ParamKind::number: n.push_back(v.key); break;
    case ParamKind::vector:
      for (std::size_t i = 0; i < v.value.vector.size(); ++i) n.push_back(v.key + "[" + std::to_string(i) + "]");
      break;
    case ParamKind::matrix:
      for (std::size_t i = 0; i < v.value.matrix.size(); ++i)
        for (std::size_t j = 0; j < v.value.matrix[i].size(); ++j)
          n.push_back(v.key + "[" + std::to_string(i) + "][" + std::to_string(j) + "]");
      break;
    case ParamKind::name: break;
  }
  return n;
}

std::vector<double> element_values(const DrawnValue& v) {
  std::vector<double> x;
  switch (v.kind) {
    case ParamKind::number: x.push_back(v.value.number); break;
    case ParamKind::vector: x = v.value.vector; break;
    case ParamKind::matrix:
      for (const auto& r : v.value.matrix) x.insert(x.end(), r.begin(), r.end());
      break;
    case ParamKind::name: break;
  }
  return x;
}

}  // namespace adcs::sim::campaign
