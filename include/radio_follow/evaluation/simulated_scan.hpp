// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <random>

#include "radio_follow/common/pose2.hpp"
#include "radio_follow/control/obstacle_avoidance.hpp"
#include "radio_follow/sim/obstacles.hpp"

namespace radio_follow {
namespace evaluation {

/// What the command pipeline's avoidance sees of one simulated scan taken at `pose`:
/// sim::noisyScan (the scan the ROS simulator publishes) through control::scanSectors, the
/// conversion the controller nodes apply to every sensor_msgs/LaserScan
/// (ControllerBase::onScan). `noise` and `rng` are the caller's; their state carries over.
/// `corridor_half_width`: the avoidance's side_threshold.
control::SectorRanges simulatedScanSectors(const sim::Obstacles& obstacles,
                                           const sim::ScanConfig& scan, const Pose2& pose,
                                           double corridor_half_width,
                                           std::normal_distribution<double>& noise,
                                           std::mt19937_64& rng);

}  // namespace evaluation
}  // namespace radio_follow
