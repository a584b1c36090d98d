// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/TransformStamped.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "radio_follow/common/error_statistics.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/odometry_placement.hpp"
#include "radio_follow/ros/locator/locator_node.hpp"

namespace radio_follow {

/// The raw sensor messages and the ground truth of a bag, in memory, in stamp order, so that one
/// bag can be replayed through many locator settings.
struct BagData {
  struct Entry {
    double t = 0.0;         ///< the message's header stamp (driver receive time), s
    double received = 0.0;  ///< when the recorder received it (the bag's time), s
    std::size_t kind = 0;   ///< its input: index into sensorInputKinds()
    std::vector<std::uint8_t> message;  ///< serialized
  };
  std::vector<Entry> entries;  ///< sorted by t
  /// The target in the robot frame (the simulator's ground_truth/target_relative), sorted
  /// by stamp.
  std::vector<geometry_msgs::PointStamped> truth;
  /// Every transform of /tf and /tf_static, sorted by when the recorder received it.
  struct Transform {
    double received = 0.0;  ///< the bag's time, s
    bool is_static = false;
    geometry_msgs::TransformStamped transform;
  };
  std::vector<Transform> tf;

  double duration() const { return entries.empty() ? 0.0 : entries.back().t - entries.front().t; }
  /// Messages of `message_type` (e.g. "radio_follow/UwbRanges").
  std::size_t count(const std::string& message_type) const;
};

/// Reads every message of an input's type (sensorInputKinds(): UwbRanges, AoaBearing,
/// TdoaMeasurements) of a bag (any topic),
/// the transforms on /tf and /tf_static and the PointStamped messages on `truth_topic`. Throws
/// std::runtime_error naming the bag when it cannot be read or holds no sensor message.
BagData loadBag(const std::string& path, const std::string& truth_topic);

/// One locator update of a replay.
struct ReplayRow {
  double t = 0.0;  ///< update time (bag time), s
  estimation::LocatorEstimate estimate;
  bool has_truth = false;
  Eigen::Vector2d truth = Eigen::Vector2d::Zero();  ///< robot frame, at the estimate's stamp
  double error = 0.0;                               ///< m, xy, when has_truth and a position
  /// A direction: OK, DEGRADED or HEADING_ONLY (whose position is a guess along it).
  bool has_heading = false;
  double heading = 0.0;  ///< rad, robot frame, of the estimate's position
  /// With a truth at the stamp: truth's bearing minus `heading`, wrapped, rad; and the
  /// miss at the target (missAtTarget), m.
  bool has_heading_truth = false;
  double heading_error = 0.0;
  double miss = 0.0;
};

struct ReplayResult {
  std::vector<ReplayRow> rows;
  ErrorStatistics statistics;  ///< over the rows with a position (OK/DEGRADED) and a truth
  /// Over the rows with a direction (OK/DEGRADED/HEADING_ONLY) and a truth, by status.
  HeadingStatistics heading;
  std::size_t refused = 0;    ///< measurements the locator refused (unknown sensors)
  SensorMatch sensors;        ///< the layout's sensors the messages named, and strangers
  double availability = 0.0;  ///< share of updates with a position
  /// Where the messages went: placed in the odometry frame, dropped in a TF gap, or in the
  /// robot frame (no odometry in the bag, or `odom_frame` empty: then all of them).
  estimation::OdometryPlacement placement;
};

/// Runs the locator over the bag exactly as the node would: messages in stamp order, an
/// update every 1/rate seconds of their time; with `params.odom_frame` set, each message
/// placed with the bag's TF `odom_frame -> layout fixed frame` at its stamp by the node's
/// own lookup (odometryPoseAt, `params.tf_tolerance`), the buffer holding the transforms
/// the recorder had received when it received the message. Estimates (robot frame) are
/// compared with the ground truth interpolated at the estimate's stamp: the position
/// (rows with one), and the direction (rows with one, HEADING_ONLY too).
ReplayResult replay(const BagData& bag, const Layout& layout, const LocatorNode::Params& params,
                    double rate);

/// summary.json: the position statistics (ErrorStatistics::toJson: overall,
/// by_sector, by_distance) plus "heading" (HeadingStatistics::toJson).
std::string summaryJson(const ReplayResult& result);

/// The rows as CSV with a header (t, status, x, y, z, sigma_x, sigma_y, truth_x, truth_y,
/// error, bearing_deg, heading_error_deg, miss_m; empty cells where there is no value).
/// x, y, z are empty for HEADING_ONLY (no position), bearing_deg is not.
std::string toCsv(const ReplayResult& result);

}  // namespace radio_follow
