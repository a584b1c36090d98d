// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/time.h>

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>

#include "radio_follow/AoaBearing.h"
#include "radio_follow/TdoaMeasurements.h"
#include "radio_follow/UwbRanges.h"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/odometry_placement.hpp"

namespace radio_follow {

/// How far from the receiver's clock a measurement's stamp may be for its odometry pose to
/// be looked up in TF, s. Far beyond any TF buffer's history (tf2's default is 10 s), so
/// no lookup that could succeed is skipped.
constexpr double kTfHorizon = 3600.0;

/// Hands driver messages to a Locator the one way both the locator node and the offline
/// evaluator do: only ranges to the target's anchor, only bearings of the target's tag
/// (when the layout names one), only TDoA differences of the target's tag (the robot's own
/// modules' blinks calibrate the anchors), a module named by its ID or else its frame,
/// every value stamped with its message's header.
class LocatorInputs {
 public:
  /// The robot's odometry pose at a stamp (TF odom -> fixed frame), or nothing.
  using PoseLookup = std::function<std::optional<Pose2>(const ros::Time& stamp)>;

  /// The receiver's clock when a message is handled, s: the node's ros::Time::now(), a
  /// replay's recording time of the message (estimation::OdometryPlacement's time base).
  using Clock = std::function<double()>;

  explicit LocatorInputs(estimation::Locator& locator) : locator_(locator) {}
  /// With a lookup, every measurement is placed in the odometry frame at its stamp
  /// (estimation::OdometryPlacement decides what happens without a pose, on `clock`).
  LocatorInputs(estimation::Locator& locator, PoseLookup lookup, Clock clock = rosNow)
      : locator_(locator), lookup_(std::move(lookup)), clock_(std::move(clock)) {}

  /// Each returns how many entries the locator refused (unknown sensor, invalid value).
  std::size_t add(const UwbRanges& msg);
  std::size_t add(const AoaBearing& msg);
  std::size_t add(const TdoaMeasurements& msg);

  /// Ranges to the target's anchor so far.
  std::size_t targetRanges() const { return target_ranges_; }
  /// Ranges to other anchors so far, by normalised anchor ID: with none to the target,
  /// the layout's target.uwb_anchor_id is probably wrong (the node warns).
  const std::map<std::string, std::size_t>& otherAnchors() const { return other_anchors_; }
  /// TDoA messages of tags that are neither the target's (Layout::isTargetTdoaTag) nor
  /// one of the robot's own TWR modules, by normalised tag ID (other people's tags).
  /// Not fused.
  const std::map<std::string, std::size_t>& otherTdoaTags() const { return other_tdoa_tags_; }
  /// TDoA messages of the robot's own TWR modules: they calibrate the anchors'
  /// offsets (Locator::addTdoaCalibration), never the estimate.
  std::size_t calibrationBlinks() const { return calibration_blinks_; }
  const estimation::OdometryPlacement& placement() const { return placement_; }

 private:
  /// The pose for a message stamped `stamp`; false: drop the message (TF gap).
  bool poseFor(const ros::Time& stamp, std::optional<Pose2>* pose);

  /// Message IDs as they arrive, resolved once each: the first message with an ID asks
  /// `resolve`, later ones find the answer here. At most kMaxIds are kept (a stream of
  /// made-up IDs is resolved every time rather than grow the table).
  class IdCache {
   public:
    template <typename Resolve>
    std::size_t operator()(const std::string& id, Resolve resolve) {
      const auto found = ids_.find(id);
      if (found != ids_.end()) {
        return found->second;
      }
      const std::size_t index = resolve(id);
      if (ids_.size() < kMaxIds) {
        ids_.emplace(id, index);
      }
      return index;
    }

   private:
    static constexpr std::size_t kMaxIds = 256;
    std::unordered_map<std::string, std::size_t> ids_;
  };

  static double rosNow() { return ros::Time::now().toSec(); }

  estimation::Locator& locator_;
  PoseLookup lookup_;
  Clock clock_;
  estimation::OdometryPlacement placement_;
  std::size_t target_ranges_ = 0;
  std::map<std::string, std::size_t> other_anchors_;
  std::map<std::string, std::size_t> other_tdoa_tags_;
  std::size_t calibration_blinks_ = 0;
  IdCache modules_;         // UwbRanges tag_id or frame -> TWR module index
  IdCache target_anchors_;  // UwbRange.anchor_id -> 0: the target's, kNoSensor: another
  IdCache boards_;          // AoaBearing frame -> AoA board index
  IdCache tdoa_anchors_;    // TdoaDifference anchor -> TDoA anchor index
  IdCache tdoa_tags_;       // TdoaMeasurements tag_id -> TWR module index (calibration)
};

}  // namespace radio_follow
