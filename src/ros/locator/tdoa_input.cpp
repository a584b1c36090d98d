// SPDX-License-Identifier: BSD-3-Clause
// The TDoA differences' input: TdoaMeasurements of the target's tag are fused; those of the
// robot's own TWR modules calibrate the anchors' offsets; other tags are counted.
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "radio_follow/TdoaMeasurements.h"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/ros/locator/locator_inputs.hpp"

namespace radio_follow {

class TdoaInput final : public MessageInput<TdoaMeasurements> {
 public:
  using MessageInput::MessageInput;

  std::string topicsParam() const override { return estimation::TdoaReading::kTopicsParam; }
  std::vector<std::string> defaultTopics(const Layout& layout) const override {
    return conventionalTopics(layout).tdoa;
  }

  std::size_t add(const TdoaMeasurements& msg) override {
    const Layout& layout = inputs_.layout();
    estimation::Locator& locator = inputs_.locator();
    const auto anchor = [&](const std::string& id) {
      return anchors_(id, [&](const std::string& a) { return layout.tdoaAnchorIndex(a); });
    };
    const double t = msg.header.stamp.toSec();
    if (!layout.isTargetTdoaTag(msg.tag_id)) {
      const std::size_t module = tags_(msg.tag_id, [&](const std::string& id) {
        return locator.tdoaCalibration().moduleOf(id).value_or(kNoSensor);
      });
      if (module != kNoSensor) {
        // One of the robot's own modules, at a known position: the anchors' offsets.
        std::size_t refused = 0;
        for (const auto& d : msg.differences) {
          refused += !locator.addTdoaCalibration(module, anchor(d.anchor_a), anchor(d.anchor_b),
                                                 d.distance_difference, t);
        }
        ++calibration_blinks_;
        return refused;
      }
      ++other_tags_[normalizeId(msg.tag_id)];  // not the person: never fused
      return 0;
    }
    std::optional<Pose2> pose;
    if (!inputs_.poseFor(msg.header.stamp, &pose)) {
      return 0;
    }
    std::size_t refused = 0;
    for (const auto& d : msg.differences) {
      refused += !locator.addTdoa(anchor(d.anchor_a), anchor(d.anchor_b), d.distance_difference,
                                  d.variance, t, pose);
    }
    return refused;
  }

  void warn(const TdoaMeasurements& /*msg*/, std::size_t refused) const override {
    if (refused > 0) {
      ROS_WARN_THROTTLE(5.0, "locator: ignoring %zu TDoA difference(s) (unknown anchor?)", refused);
    }
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) const override {
    std::size_t other = 0;
    for (const auto& entry : other_tags_) {
      other += entry.second;
    }
    status.add("TDoA messages of other tags (not fused)", other);
    status.add("TDoA calibration blinks (robot's modules)", calibration_blinks_);
    const estimation::Locator& locator = inputs_.locator();
    status.add("TDoA differences awaiting calibration", locator.stats().tdoa_uncalibrated);
    const Layout& layout = locator.layout();
    for (const auto& pair : locator.tdoaCalibration().pairs()) {
      const std::string name = "TDoA offset " + layout.tdoa_anchors[pair.a].id + "-" +
                               layout.tdoa_anchors[pair.b].id + " (m)";
      char value[64];
      if (pair.offset) {
        std::snprintf(value, sizeof(value), "%.3f (%zu blinks)", *pair.offset, pair.samples);
      } else {
        std::snprintf(value, sizeof(value), "learning (%zu blinks)", pair.samples);
      }
      status.add(name, std::string(value));
    }
  }

 private:
  /// Messages of tags that are neither the target's (Layout::isTargetTdoaTag) nor one of
  /// the robot's own TWR modules, by normalised tag ID (other people's tags).
  std::map<std::string, std::size_t> other_tags_;
  /// Messages of the robot's own TWR modules: they calibrate the anchors' offsets
  /// (Locator::addTdoaCalibration), never the estimate.
  std::size_t calibration_blinks_ = 0;
  IdCache anchors_;  // TdoaDifference anchor -> TDoA anchor index
  IdCache tags_;     // TdoaMeasurements tag_id -> TWR module index (calibration)
};

std::unique_ptr<SensorInput> makeTdoaInput(LocatorInputs& inputs) {
  return std::make_unique<TdoaInput>(inputs);
}

}  // namespace radio_follow
