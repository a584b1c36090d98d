// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/virtual_sensors.hpp"

#include <algorithm>
#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/models/sensor_tables.hpp"

namespace radio_follow {
namespace sim {
namespace {

bool chance(double probability, Rng& rng) {
  return probability > 0.0 && std::uniform_real_distribution<double>(0.0, 1.0)(rng) < probability;
}

double gaussian(double sigma, Rng& rng) {
  return sigma > 0.0 ? std::normal_distribution<double>(0.0, sigma)(rng) : 0.0;
}

}  // namespace

bool OcclusionSector::contains(double bearing) const {
  const double width = wrapAngleFast(bearing_max - bearing_min);
  const double offset = wrapAngleFast(bearing - bearing_min);
  const double span = width <= 0.0 ? width + 2.0 * kPi : width;
  const double pos = offset < 0.0 ? offset + 2.0 * kPi : offset;
  return pos <= span;
}

std::optional<double> simulateTwrRange(const TwrModule& module, const TwrNoise& noise,
                                       const Eigen::Vector3d& target, Rng& rng) {
  if (chance(noise.dropout_probability, rng)) {
    return std::nullopt;
  }
  const Eigen::Vector3d offset = target - module.position;
  const double distance = offset.norm();
  const models::RangeError error = models::uwbRangeError(distance);
  double range = distance + (noise.use_table_bias ? error.bias : 0.0) +
                 gaussian(noise.sigma_scale * error.sigma, rng);
  const double bearing = std::atan2(offset.y(), offset.x());
  for (const auto& sector : noise.occlusions) {
    const bool applies = sector.module.empty() || sector.module == module.id;
    if (applies && sector.contains(bearing) && chance(sector.reflection_probability, rng)) {
      range += sector.reflection_extra;
    }
  }
  return std::max(0.0, range);
}

std::optional<AoaSample> simulateAoa(const AoaBoard& board, const AoaNoise& noise,
                                     const Eigen::Vector3d& target, Rng& rng) {
  const Eigen::Vector3d local = board.orientation.conjugate() * (target - board.position);
  const double distance = local.norm();
  if (distance > noise.max_range || distance < 1e-6 || chance(noise.dropout_probability, rng)) {
    return std::nullopt;
  }
  AoaSample sample;
  sample.behind = local.x() < 0.0;
  // The array sees the direction mirrored through its own plane when the tag is behind.
  const Eigen::Vector3d seen(std::abs(local.x()), local.y(), local.z());
  const double azimuth = std::atan2(seen.y(), seen.x());
  const double elevation = std::atan2(seen.z(), std::hypot(seen.x(), seen.y()));

  // The tables are in the device's sign convention (clockwise): look up and perturb there.
  const double device_azimuth = -azimuth;
  const models::AoaError error = models::aoaError(board.kind, device_azimuth, distance);
  const double measured_device = device_azimuth +
                                 (noise.use_table_bias ? error.azimuth_bias : 0.0) +
                                 gaussian(noise.sigma_scale * error.azimuth_sigma, rng);
  // The board reports both angles in [-90, 90] deg (u-connectLocate): noise near the
  // edge of its hemisphere saturates there, as the real output does, instead of wrapping
  // into values no device writes (the drivers refuse them as implausible).
  sample.azimuth = std::clamp(wrapAngleFast(-measured_device), -kPi / 2.0, kPi / 2.0);
  sample.elevation = std::clamp(elevation + gaussian(noise.sigma_scale * error.azimuth_sigma, rng),
                                -kPi / 2.0, kPi / 2.0);
  sample.rssi = error.rssi_mean + gaussian(error.rssi_sigma, rng) -
                (sample.behind ? noise.behind_rssi_drop : 0.0);
  sample.rssi_second = sample.rssi + noise.second_polarisation_offset + gaussian(1.0, rng);
  return sample;
}

std::vector<double> simulateTdoa(const std::vector<TdoaAnchor>& anchors, std::size_t reference,
                                 double sigma, const Eigen::Vector3d& target, Rng& rng) {
  std::vector<double> differences;
  if (reference >= anchors.size()) {
    return differences;
  }
  const double to_reference = (target - anchors[reference].position).norm();
  for (std::size_t i = 0; i < anchors.size(); ++i) {
    if (i != reference) {
      differences.push_back((target - anchors[i].position).norm() - to_reference +
                            gaussian(sigma, rng));
    }
  }
  return differences;
}

}  // namespace sim
}  // namespace radio_follow
