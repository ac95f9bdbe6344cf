#pragma once
// Parameters declared once and bound to fields (issue 17). A scenario's configuration struct
// lists each parameter once, with its key, default, unit and source, in a visit():
//
//   struct Config {
//     double K_Nm;  Vec3 P_Nms;  std::string integrator;
//     template <class F> void visit(F&& f) {
//       f.number("K_Nm", K_Nm, 0.01, "N m", "ours: critically damped at 0.1 rad/s");
//       f.vec("P_Nms", P_Nms, Vec3(0.2, 0.2, 0.2), "N m s", "ours");
//       f.name("integrator", integrator, "adams", {"adams", "bdf", "rk4"}, "CVODE Adams (truth)");
//     }
//   };
//   declare:  declare_config<Config>(params);          (Scenario::declare)
//   run:      const Config c = read_config<Config>(params);   (Scenario::run)
//
// A Config may hold members that are not parameters but choose the list or the defaults (a
// scenario's variant); pass a prototype with them set: declare_config(params, Config{variant}).
//
// so the key is spelled once and the field is the only place the value lives. (The default
// is a non-deduced argument, so an Eigen expression such as Mat3::Identity() binds to it.)
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "adcs/core/types.hpp"
#include "scenarios/params.hpp"

namespace adcs::sim {

//! The visitor that declares each parameter (defaults, units and sources go to the ParamSet).
class ParamDeclarer {
 public:
  explicit ParamDeclarer(ParamSet& p) : p_(p) {}
  void number(const std::string& key, double&, double def, std::string unit, std::string source) {
    p_.number(key, def, std::move(unit), std::move(source));
  }
  template <int N>
  void vec(const std::string& key, Vec<N>&, const std::enable_if_t<true, Vec<N>>& def, std::string unit, std::string source) {
    p_.vector(key, std::vector<double>(def.data(), def.data() + N), std::move(unit), std::move(source));
  }
  template <int R, int C>
  void mat(const std::string& key, Mat<R, C>&, const std::enable_if_t<true, Mat<R, C>>& def, std::string unit, std::string source) {
    std::vector<std::vector<double>> m(R, std::vector<double>(C));
    for (int i = 0; i < R; ++i)
      for (int j = 0; j < C; ++j) m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = def(i, j);
    p_.matrix(key, std::move(m), std::move(unit), std::move(source));
  }
  void name(const std::string& key, std::string&, std::string def, std::vector<std::string> allowed,
            std::string source) {
    p_.name(key, std::move(def), std::move(allowed), std::move(source));
  }

 private:
  ParamSet& p_;
};

//! The visitor that reads each parameter's value (as set by --set or the file) into its field.
class ParamReader {
 public:
  explicit ParamReader(const ParamSet& p) : p_(p) {}
  void number(const std::string& key, double& field, double, const std::string&, const std::string&) const {
    field = p_.get_number(key);
  }
  template <int N>
  void vec(const std::string& key, Vec<N>& field, const std::enable_if_t<true, Vec<N>>&, const std::string&, const std::string&) const {
    field = p_.get_vec<N>(key);
  }
  template <int R, int C>
  void mat(const std::string& key, Mat<R, C>& field, const std::enable_if_t<true, Mat<R, C>>&, const std::string&, const std::string&) const {
    field = p_.get_mat<R, C>(key);
  }
  void name(const std::string& key, std::string& field, const std::string&, const std::vector<std::string>&,
            const std::string&) const {
    field = p_.get_name(key);
  }

 private:
  const ParamSet& p_;
};

//! Declares every parameter Config::visit lists. `prototype` carries what is not a parameter
//! but chooses the list or its defaults (a scenario's variant: which law, which vehicle).
template <class Config>
void declare_config(ParamSet& p, Config prototype = {}) {
  prototype.visit(ParamDeclarer{p});
}

//! The parameters' values, read into a copy of `prototype` (see declare_config).
template <class Config>
Config read_config(const ParamSet& p, Config prototype = {}) {
  prototype.visit(ParamReader{p});
  return prototype;
}

}  // namespace adcs::sim
