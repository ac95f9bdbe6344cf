#pragma once
// The ground sensor model of a vehicle file (issue 18): a rate gyro and a star tracker, each
// optional (absent = perfect), and what the controller is given:
//   rate      the gyro measurement ω_m = ω + b + n, n ~ N(0, arw²/T) per axis (white rate noise
//             of spectral density arw², averaged over the control period T), the bias b starting
//             at bias_rad_s and walking b += rrw √T w, w ~ N(0, I), after every sample;
//   attitude  the star-tracker attitude at a valid star-tracker sample (the truth turned by a
//             small rotation θ ~ N(0, noise² I), B components); at any other sample the last
//             attitude propagated over T with the rate measured at the previous sample, held
//             (C_BN ← exp(−[ω_m T]×) C_BN). This gyro-propagated attitude is part of the ground
//             sensor model, NOT an on-board estimator; it starts from the true initial attitude.
// Noise comes from RunContext::seed through the portable Rng (sim/random.hpp), one stream per
// sensor ("sensors.gyro", "sensors.star_tracker"), so adding a sensor leaves the other's noise as
// it was and the same seed gives the same run on every machine. Every sample draws the same
// count of numbers whatever the values (a dropout probability of 0 still draws its uniform), so
// changing a noise level never shifts the other draws.
#include <cstdint>
#include <optional>

#include "adcs/core/signals.hpp"
#include "sim/random.hpp"
#include "vehicle/config.hpp"

namespace adcs::sim::vehicle {

class SensorModel {
 public:
  SensorModel(const std::optional<GyroConfig>& gyro, const std::optional<StarTrackerConfig>& star_tracker,
              double control_period_s, std::uint64_t seed);

  //! The measurement at the next control sample (call once per sample, in order) from the true
  //! attitude and rate.
  AttitudeState measure(const AttitudeState& truth);

  //! The star tracker's last sample was valid (true without a star tracker).
  bool star_tracker_valid() const noexcept { return st_valid_; }
  long star_tracker_samples() const noexcept { return st_samples_; }
  long star_tracker_dropouts() const noexcept { return st_dropouts_; }
  //! [rad/s] the gyro bias in force (zero without a gyro).
  const Vec3& gyro_bias() const noexcept { return bias_; }

 private:
  Vec3 gyro(const Vec3& omega_true);
  Vec3 attitude(const Vec3& sigma_true);

  std::optional<GyroConfig> gyro_;
  std::optional<StarTrackerConfig> st_;
  double period_s_;
  Rng gyro_rng_, st_rng_;
  Vec3 bias_ = Vec3::Zero();
  long sample_ = 0;
  bool st_valid_ = true;
  long st_samples_ = 0, st_dropouts_ = 0;
  Vec3 sigma_est_ = Vec3::Zero();  //!< the attitude given at the last sample
  Vec3 omega_last_ = Vec3::Zero();  //!< [rad/s] the rate measured at the last sample
};

}  // namespace adcs::sim::vehicle
