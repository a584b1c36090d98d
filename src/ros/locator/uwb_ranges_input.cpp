// SPDX-License-Identifier: BSD-3-Clause
// The TWR ranges' input: UwbRanges of the robot's modules, only the ranges to the target's
// anchor, a module named by its ID or else its frame.
#include <map>
#include <memory>
#include <set>
#include <string>

#include "radio_follow/UwbRanges.h"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/ros/locator/locator_inputs.hpp"

namespace radio_follow {

class UwbRangesInput final : public MessageInput<UwbRanges> {
 public:
  using MessageInput::MessageInput;

  std::string topicsParam() const override { return estimation::RangeReading::kTopicsParam; }
  std::vector<std::string> defaultTopics(const Layout& layout) const override {
    return conventionalTopics(layout).uwb;
  }

  std::size_t add(const UwbRanges& msg) override {
    // The module is named by its ID; drivers started without one still set their frame.
    // IDs compare normalised (upper case), as the layout parser stores them: a layout
    // saying "da12" and a driver printing "DA12" mean the same anchor. (The module lookup,
    // Layout::findTwrModule, normalises the module ID itself.)
    const Layout& layout = inputs_.layout();
    const std::string& name = msg.tag_id.empty() ? msg.header.frame_id : msg.tag_id;
    const std::size_t module =
        modules_(name, [&](const std::string& id) { return layout.twrModuleIndex(id); });
    if (module == kNoSensor) {
      strangers_.insert("module " + name);
    } else {
      heard_.insert(module);
    }
    std::optional<Pose2> pose;
    if (!inputs_.poseFor(msg.header.stamp, &pose)) {
      return 0;  // counted by the placement
    }
    std::size_t refused = 0;
    for (const auto& range : msg.ranges) {
      const bool target = target_anchors_(range.anchor_id, [&](const std::string& id) {
                            return normalizeId(id) == layout.target_anchor_id ? 0 : kNoSensor;
                          }) == 0;
      if (!target) {
        ++other_anchors_[normalizeId(range.anchor_id)];  // another anchor, or a wrong layout
        continue;
      }
      ++target_ranges_;
      refused += !inputs_.locator().add(msg.header.stamp.toSec(),
                                        estimation::RangeReading{module, range.range}, pose);
    }
    return refused;
  }

  void warn(const UwbRanges& msg, std::size_t refused) const override {
    if (refused > 0) {
      ROS_WARN_THROTTLE(5.0, "locator: ignoring range from unknown module '%s' or invalid value",
                        (msg.tag_id.empty() ? msg.header.frame_id : msg.tag_id).c_str());
    }
    if (target_ranges_ == 0 && !other_anchors_.empty()) {
      // Ranges arrive, none to the target: a wrong target.uwb_anchor_id leaves the
      // estimate LOST for good, so say which anchors are heard.
      std::string heard;
      for (const auto& [anchor, count] : other_anchors_) {
        heard += (heard.empty() ? "" : ", ") + anchor;
      }
      ROS_WARN_THROTTLE(5.0,
                        "locator: ranges to anchor(s) %s but none to the layout's target "
                        "'%s' (target.uwb_anchor_id in the layout file)",
                        heard.c_str(), inputs_.layout().target_anchor_id.c_str());
    }
  }

  void match(SensorMatch& match) const override {
    for (const std::size_t module : heard_) {
      match.heard.insert(inputs_.layout().twr_modules[module].id);
    }
    match.strangers.insert(strangers_.begin(), strangers_.end());
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) const override {
    std::size_t other = 0;
    for (const auto& entry : other_anchors_) {
      other += entry.second;
    }
    status.add("ranges to the target anchor", target_ranges_);
    status.add("ranges to other anchors", other);
  }

 private:
  std::size_t target_ranges_ = 0;
  /// Ranges to other anchors, by normalised anchor ID: with none to the target, the
  /// layout's target.uwb_anchor_id is probably wrong (warn()).
  std::map<std::string, std::size_t> other_anchors_;
  std::set<std::size_t> heard_;      // modules named
  std::set<std::string> strangers_;  // names the layout does not have
  IdCache modules_;                  // UwbRanges tag_id or frame -> TWR module index
  IdCache target_anchors_;           // UwbRange.anchor_id -> 0: the target's, kNoSensor: another
};

std::unique_ptr<SensorInput> makeUwbRangesInput(LocatorInputs& inputs) {
  return std::make_unique<UwbRangesInput>(inputs);
}

}  // namespace radio_follow
