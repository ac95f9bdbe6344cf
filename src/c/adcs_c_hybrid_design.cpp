// The C interface (include/adcs/c/adcs.h): the ground design of seed 001's gains,
// adcs_hybrid_design_gains, in double (pole placement and the Schur-based Lyapunov solve,
// adcs::design_hybrid_adaptive_gains). A unit of its own: a flight build that uploads its gains
// (adcs_hybrid43_init, adcs_hybrid43f_init take K and P) compiles none of the solve; the Cortex-M
// builds here leave it out.
#include "adcs/c/adcs.h"
#include "adcs/control/hybrid_adaptive.hpp"
#include "c_api_common.hpp"

namespace adcs::c_api {
namespace {

adcs_status design_gains(const double (*re)[2], const double (*im)[2], const double (*Q_L)[6], double (*K)[6],
                         double (*P)[6]) noexcept {
  if (re == nullptr || im == nullptr || Q_L == nullptr || K == nullptr || P == nullptr)
    return ADCS_STATUS_INVALID_PARAMETER;
  AxisPoles<3> poles;
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < 2; ++k) poles[a][k] = {re[a][k], im[a][k]};
  HybridAdaptiveGains<double> g;
  const Mat6 Q = Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(&Q_L[0][0]);
  const Status s = design_hybrid_adaptive_gains(poles, Q, g);
  if (s != Status::ok) return static_cast<adcs_status>(s);
  Eigen::Map<Eigen::Matrix<double, 3, 6, Eigen::RowMajor>> K_out(&K[0][0]);
  Eigen::Map<Eigen::Matrix<double, 6, 6, Eigen::RowMajor>> P_out(&P[0][0]);
  K_out = g.K;
  P_out = g.P;
  return ADCS_STATUS_OK;
}

}  // namespace
}  // namespace adcs::c_api

extern "C" adcs_status adcs_hybrid_design_gains(const double poles_re[3][2], const double poles_im[3][2],
                                                const double Q_L[6][6], double K[3][6], double P[6][6]) {
  return adcs::c_api::design_gains(poles_re, poles_im, Q_L, K, P);
}
