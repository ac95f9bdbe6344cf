#include "vehicle/sensors.hpp"

#include <cmath>

#include "adcs/math/mrp.hpp"
#include "adcs/math/so3.hpp"
#include "campaign/seeding.hpp"

namespace adcs::sim::vehicle {

SensorModel::SensorModel(const std::optional<GyroConfig>& gyro, const std::optional<StarTrackerConfig>& star_tracker,
                         double control_period_s, std::uint64_t seed)
    : gyro_(gyro),
      st_(star_tracker),
      period_s_(control_period_s),
      // One named stream per sensor (campaign/seeding.hpp's counter-based seeding): a sensor's
      // noise does not depend on which other sensors the file has.
      gyro_rng_(campaign::stream(seed, 0, "sensors.gyro")),
      st_rng_(campaign::stream(seed, 0, "sensors.star_tracker")) {
  if (gyro_) bias_ = gyro_->bias_rad_s;
}

AttitudeState SensorModel::measure(const AttitudeState& truth) {
  AttitudeState m;
  m.sigma_BN = attitude(truth.sigma_BN);  // propagates with the rate measured at the last sample
  m.omega_BN_B = gyro(truth.omega_BN_B);
  omega_last_ = m.omega_BN_B;
  ++sample_;
  return m;
}

Vec3 SensorModel::gyro(const Vec3& omega_true) {
  if (!gyro_) return omega_true;  // perfect rate
  // White rate noise of spectral density arw² averaged over T: standard deviation arw/√T.
  const double sd = gyro_->arw_rad_sqrt_s / std::sqrt(period_s_);
  Vec3 noise;
  for (int i = 0; i < 3; ++i) noise(i) = sd * gyro_rng_.normal();
  const Vec3 measured = omega_true + bias_ + noise;
  // Rate random walk of the bias over the next period: increments of variance rrw² T.
  const double step = gyro_->rrw_rad_s_sqrt_s * std::sqrt(period_s_);
  for (int i = 0; i < 3; ++i) bias_(i) += step * gyro_rng_.normal();
  return measured;
}

Vec3 SensorModel::attitude(const Vec3& sigma_true) {
  if (!st_) return sigma_true;  // perfect attitude
  if (sample_ == 0) sigma_est_ = sigma_true;  // the propagation starts from the true attitude
  else  // C_BN(t + T) = exp(-[omega T]x) C_BN(t) for a rate held over T
    sigma_est_ = dcm_to_mrp(so3_exp(-period_s_ * omega_last_) * mrp_to_dcm(sigma_est_));
  st_valid_ = false;
  if (sample_ % st_->every_samples != 0) return sigma_est_;
  ++st_samples_;
  // Always the same draws per star-tracker sample: the dropout uniform, then the 3 noise angles.
  const bool dropped = st_rng_.uniform01() < st_->dropout_probability;
  Vec3 theta;
  for (int i = 0; i < 3; ++i) theta(i) = st_->noise_rad * st_rng_.normal();
  if (dropped) {
    ++st_dropouts_;
    return sigma_est_;
  }
  st_valid_ = true;
  // The measured attitude: the true one turned by the small rotation theta (B components).
  sigma_est_ = dcm_to_mrp(so3_exp(-theta) * mrp_to_dcm(sigma_true));
  return sigma_est_;
}

}  // namespace adcs::sim::vehicle
