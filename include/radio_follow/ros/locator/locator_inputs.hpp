// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/time.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/odometry_placement.hpp"
#include "radio_follow/ros/locator/sensor_input.hpp"

namespace radio_follow {

/// How far from the receiver's clock a measurement's stamp may be for its odometry pose to
/// be looked up in TF, s. Far beyond any TF buffer's history (tf2's default is 10 s), so
/// no lookup that could succeed is skipped.
constexpr double kTfHorizon = 3600.0;

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

/// Hands driver messages to a Locator the one way both the locator node and the offline
/// replay do: through every kind's SensorInput (sensorInputKinds()), each message's
/// readings stamped with its header and, with a pose lookup, placed in the odometry frame.
class LocatorInputs {
 public:
  /// The robot's odometry pose at a stamp (TF odom -> fixed frame), or nothing.
  using PoseLookup = std::function<std::optional<Pose2>(const ros::Time& stamp)>;

  /// The receiver's clock when a message is handled, s: the node's ros::Time::now(), a
  /// replay's recording time of the message (estimation::OdometryPlacement's time base).
  using Clock = std::function<double()>;

  explicit LocatorInputs(estimation::Locator& locator);
  /// With a lookup, every measurement is placed in the odometry frame at its stamp
  /// (estimation::OdometryPlacement decides what happens without a pose, on `clock`).
  LocatorInputs(estimation::Locator& locator, PoseLookup lookup, Clock clock = rosNow);
  LocatorInputs(const LocatorInputs&) = delete;
  LocatorInputs& operator=(const LocatorInputs&) = delete;

  /// A message of any kind: its input's add (the replay); 0 when no input takes it.
  template <typename Message>
  std::size_t add(const Message& msg) {
    for (const auto& input : inputs_) {
      if (auto* typed = dynamic_cast<MessageInput<Message>*>(input.get())) {
        return typed->add(msg);
      }
    }
    return 0;
  }

  /// Every kind's input, in sensorInputKinds() order.
  const std::vector<std::unique_ptr<SensorInput>>& inputs() const { return inputs_; }
  /// What every input's messages named so far.
  SensorMatch match() const {
    SensorMatch m;
    for (const auto& input : inputs_) {
      input->match(m);
    }
    return m;
  }

  // For the inputs.
  estimation::Locator& locator() { return locator_; }
  const Layout& layout() const { return locator_.layout(); }
  /// The pose for a message stamped `stamp`; false: drop the message (TF gap, counted by
  /// the placement).
  bool poseFor(const ros::Time& stamp, std::optional<Pose2>* pose);

  const estimation::OdometryPlacement& placement() const { return placement_; }

 private:
  static double rosNow() { return ros::Time::now().toSec(); }

  estimation::Locator& locator_;
  PoseLookup lookup_;
  Clock clock_;
  estimation::OdometryPlacement placement_;
  std::vector<std::unique_ptr<SensorInput>> inputs_;
};

}  // namespace radio_follow
