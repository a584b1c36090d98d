// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"

namespace radio_follow {
namespace sim {

using Rng = std::mt19937_64;

/// A direction sector (seen from a UWB module, in the robot's fixed frame) in which
/// the direct path is blocked, e.g. the Spot's LiDAR mount (thesis Section 5.3): the
/// range then jumps between the true value and a longer, reflected one.
struct OcclusionSector {
  std::string module;                   ///< TWR module ID it blocks; empty = every module
  double bearing_min = 0.0;             ///< rad, counter-clockwise from the robot's x axis
  double bearing_max = 0.0;             ///< rad; the sector may wrap through +-pi
  double reflection_extra = 0.8;        ///< m added to the range when the reflection is read
  double reflection_probability = 0.5;  ///< share of epochs that read the reflection

  bool contains(double bearing) const;
};

/// Noise model of one simulated UWB TWR module.
struct TwrNoise {
  bool use_table_bias = true;        ///< add Table 3.1's distance-dependent bias
  double sigma_scale = 1.0;          ///< multiplies Table 3.1's sigma
  double dropout_probability = 0.0;  ///< chance an epoch reports nothing
  std::vector<OcclusionSector> occlusions;
};

/// Noise model of one simulated AoA board.
struct AoaNoise {
  double sigma_scale = 1.0;                  ///< multiplies the tables' azimuth sigma
  bool use_table_bias = true;                ///< add the tables' mean azimuth error
  double dropout_probability = 0.0;          ///< chance an event is lost
  double max_range = 15.0;                   ///< m; no events beyond
  double behind_rssi_drop = 6.0;             ///< dB weaker when the tag is behind the board
  double second_polarisation_offset = -3.0;  ///< dB, rssi_second relative to rssi
};

/// One simulated bearing, in the board frame with the package's convention
/// (azimuth counter-clockwise about z, i.e. already inverted from the device's sign).
struct AoaSample {
  double azimuth = 0.0;    ///< rad
  double elevation = 0.0;  ///< rad
  double rssi = 0.0;       ///< dBm
  double rssi_second = 0.0;
  bool behind = false;  ///< ground truth: the tag was behind the board (garbage angles)
};

/// A range the module would report for a target at `target` (fixed frame, m), or
/// nothing (dropout). Includes bias, noise and occlusion reflections.
std::optional<double> simulateTwrRange(const TwrModule& module, const TwrNoise& noise,
                                       const Eigen::Vector3d& target, Rng& rng);

/// A bearing the board would report for a target at `target` (fixed frame, m).
/// In front: the tables' bias and sigma at the true azimuth and distance. Behind the
/// board the array cannot tell front from back, so it reports the mirror direction
/// (plausible angles, slightly weaker RSSI): a trap the locator must not fall into.
std::optional<AoaSample> simulateAoa(const AoaBoard& board, const AoaNoise& noise,
                                     const Eigen::Vector3d& target, Rng& rng);

/// Distance differences |p - a_i| - |p - a_ref| for every anchor i != reference, with
/// Gaussian noise `sigma` (m; the thesis: 1 ns of timing error = 0.3 m).
std::vector<double> simulateTdoa(const std::vector<TdoaAnchor>& anchors, std::size_t reference,
                                 double sigma, const Eigen::Vector3d& target, Rng& rng);

}  // namespace sim
}  // namespace radio_follow
