// SPDX-License-Identifier: BSD-3-Clause
// The AoA bearings' input: AoaBearing of the robot's boards, only of the target's tag when
// the layout names one, a board named by its frame.
#include <memory>
#include <set>
#include <string>

#include "radio_follow/AoaBearing.h"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/ros/locator/locator_inputs.hpp"

namespace radio_follow {

class AoaBearingInput final : public MessageInput<AoaBearing> {
 public:
  using MessageInput::MessageInput;

  std::string topicsParam() const override { return estimation::BearingReading::kTopicsParam; }
  std::vector<std::string> defaultTopics(const Layout& layout) const override {
    return conventionalTopics(layout).aoa;
  }

  std::size_t add(const AoaBearing& msg) override {
    const std::size_t board = boards_(msg.header.frame_id, [&](const std::string& id) {
      return inputs_.layout().aoaBoardIndex(id);
    });
    if (board == kNoSensor) {
      strangers_.insert("board frame " + msg.header.frame_id);
    } else {
      heard_.insert(board);
    }
    const std::string& tag = inputs_.layout().target_tag_id;
    if (!tag.empty() && normalizeId(msg.tag_id) != tag) {
      return 0;
    }
    std::optional<Pose2> pose;
    if (!inputs_.poseFor(msg.header.stamp, &pose)) {
      return 0;
    }
    return !inputs_.locator().add(
        msg.header.stamp.toSec(),
        estimation::BearingReading{board, msg.azimuth, msg.elevation, msg.rssi}, pose);
  }

  void match(SensorMatch& match) const override {
    for (const std::size_t board : heard_) {
      match.heard.insert(inputs_.layout().aoa_boards[board].id);
    }
    match.strangers.insert(strangers_.begin(), strangers_.end());
  }

  void warn(const AoaBearing& msg, std::size_t refused) const override {
    if (refused > 0) {
      ROS_WARN_THROTTLE(5.0, "locator: ignoring bearing from unknown board frame '%s'",
                        msg.header.frame_id.c_str());
    }
  }

 private:
  std::set<std::size_t> heard_;      // boards named
  std::set<std::string> strangers_;  // frames the layout does not have
  IdCache boards_;                   // AoaBearing frame -> AoA board index
};

std::unique_ptr<SensorInput> makeAoaBearingInput(LocatorInputs& inputs) {
  return std::make_unique<AoaBearingInput>(inputs);
}

}  // namespace radio_follow
