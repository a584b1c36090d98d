// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/synthetic_observations.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {
namespace estimation {

ObservationSet idealObservations(const Layout& layout, const Eigen::Vector3d& p,
                                 const SyntheticNoise& noise, int max_bearings) {
  ObservationSet obs;
  for (const auto& module : layout.twr_modules) {
    RangeObservation z;
    z.module = module.position;
    z.range = (p - module.position).norm();
    z.sigma = noise.range_sigma;
    obs.ranges.push_back(z);
  }
  // Boards sorted by the angle between boresight and target: best aligned first.
  std::vector<std::pair<double, const AoaBoard*>> visible;
  for (const auto& board : layout.aoa_boards) {
    const Eigen::Vector3d v = p - board.position;
    const double off_axis = std::acos(
        std::clamp(board.orientation.toRotationMatrix().col(0).dot(v.normalized()), -1.0, 1.0));
    if (off_axis <= board.field_of_view) {
      visible.emplace_back(off_axis, &board);
    }
  }
  std::sort(visible.begin(), visible.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (int k = 0; k < std::min<int>(max_bearings, static_cast<int>(visible.size())); ++k) {
    const AoaBoard& board = *visible[static_cast<std::size_t>(k)].second;
    BearingObservation z;
    z.board = board.position;
    z.rotation = board.orientation.toRotationMatrix();
    const Eigen::Vector2d ae = predictBearing(p, z.board, z.rotation);
    z.azimuth = ae(0);
    z.elevation = ae(1);
    z.sigma_azimuth = noise.azimuth_sigma;
    z.sigma_elevation = noise.elevation_sigma;
    z.use_elevation = noise.use_elevation;
    obs.bearings.push_back(z);
  }
  return obs;
}

void addGaussianNoise(ObservationSet& observations, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  for (auto& z : observations.ranges)
    z.range += z.sigma * normal(rng);
  for (auto& z : observations.tdoas)
    z.difference += z.sigma * normal(rng);
  for (auto& z : observations.bearings) {
    z.azimuth = wrapAngleFast(z.azimuth + z.sigma_azimuth * normal(rng));
    z.elevation += z.sigma_elevation * normal(rng);
  }
}

}  // namespace estimation
}  // namespace radio_follow
