// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/simulated_scan.hpp"

namespace radio_follow {
namespace evaluation {

control::SectorRanges simulatedScanSectors(const sim::Obstacles& obstacles,
                                           const sim::ScanConfig& scan, const Pose2& pose,
                                           double corridor_half_width,
                                           std::normal_distribution<double>& noise,
                                           std::mt19937_64& rng) {
  return control::scanSectors(sim::noisyScan(obstacles, scan, pose, noise, rng), scan.angle_min,
                              scan.angleIncrement(), scan.range_min, scan.range_max,
                              corridor_half_width);
}

}  // namespace evaluation
}  // namespace radio_follow
