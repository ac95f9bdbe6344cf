// Uses the installed umbrella header; exits 0 only if the library computes correctly.
#include <adcs/adcs.hpp>

#include <cstdio>

int main() {
  const adcs::Vec3 sigma_BN(0.1, -0.2, 0.3);
  const adcs::Mat3 C = adcs::mrp_to_dcm(sigma_BN);
  const double orth_err = (C * C.transpose() - adcs::Mat3::Identity()).norm();
  const adcs::Vec3 back = adcs::dcm_to_mrp(C);
  const double round_trip = (back - sigma_BN).norm();
  std::printf("adcs consumer: orthogonality %.3g, round trip %.3g\n", orth_err, round_trip);
  return (orth_err < 1e-12 && round_trip < 1e-12) ? 0 : 1;
}
