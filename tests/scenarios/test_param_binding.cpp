// Parameters declared once and bound to fields (scenarios/param_binding.hpp).
#include <gtest/gtest.h>
#include "scenarios/param_binding.hpp"
namespace ADCS_UNITY_ID {
struct Cfg {
  double K = 0; adcs::Vec3 P = adcs::Vec3::Zero(); adcs::Mat3 J = adcs::Mat3::Zero(); std::string integ;
  template <class F> void visit(F&& f) {
    f.number("K_Nm", K, 0.01, "N m", "ours");
    f.vec("P_Nms", P, adcs::Vec3(0.1, 0.2, 0.3), "N m s", "ours");
    f.mat("J_kgm2", J, adcs::Mat3::Identity(), "kg m^2", "ours");
    f.name("integrator", integ, "adams", {"adams", "rk4"}, "ours");
  }
};
}
using namespace ADCS_UNITY_ID;  // as an anonymous namespace would (CMakeLists.txt, adcs_unity)
TEST(ParamBinding, DeclaredOnceReadIntoFields) {
  adcs::sim::ParamSet p;
  adcs::sim::declare_config<Cfg>(p);
  EXPECT_EQ(p.size(), 4u);
  EXPECT_EQ(p.at("K_Nm").unit, "N m");
  p.set("K_Nm", "0.5");
  p.set("integrator", "rk4");
  const Cfg c = adcs::sim::read_config<Cfg>(p);
  EXPECT_EQ(c.K, 0.5);
  EXPECT_EQ(c.P, adcs::Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(c.J, adcs::Mat3::Identity());
  EXPECT_EQ(c.integ, "rk4");
}
