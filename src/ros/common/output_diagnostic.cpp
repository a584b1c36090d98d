// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/common/output_diagnostic.hpp"

namespace radio_follow {

OutputDiagnostic::Bounds OutputDiagnostic::Bounds::forDriver(double silence_timeout,
                                                             double max_hz) {
  Bounds bounds;
  bounds.min_hz = 1.0 / silence_timeout;
  bounds.max_hz = max_hz;
  bounds.max_age = silence_timeout;
  return bounds;
}

OutputDiagnostic::OutputDiagnostic(diagnostic_updater::Updater& updater, const std::string& label,
                                   const ros::Publisher& publisher, const Bounds& bounds,
                                   bool stamped)
    : updater_(updater),
      name_(label + " " + publisher.getTopic()),
      stamped_output_(stamped),
      bounds_(bounds) {
  if (bounds_.min_hz > 0.0) {
    std::call_once(created_, [this] { create(); });
  }
  ROS_DEBUG_NAMED("wiring", "%s: publishes %s (rate diagnostic %.2f-%.2f Hz%s)",
                  ros::this_node::getName().c_str(), publisher.getTopic().c_str(), bounds_.min_hz,
                  bounds_.max_hz, stamped ? ", stamp age checked" : "");
}

void OutputDiagnostic::create() {
  const diagnostic_updater::FrequencyStatusParam rate(&bounds_.min_hz, &bounds_.max_hz, 0.1, 5);
  if (stamped_output_) {
    stamped_ = std::make_unique<diagnostic_updater::TopicDiagnostic>(
        name_, updater_, rate,
        diagnostic_updater::TimeStampStatusParam(bounds_.min_age, bounds_.max_age));
  } else {
    headerless_ =
        std::make_unique<diagnostic_updater::HeaderlessTopicDiagnostic>(name_, updater_, rate);
  }
}

void OutputDiagnostic::tick(const ros::Time& stamp) {
  std::call_once(created_, [this] { create(); });
  if (stamped_) {
    stamped_->tick(stamp);
  } else {
    headerless_->tick();
  }
}

void OutputDiagnostic::tick() {
  std::call_once(created_, [this] { create(); });
  if (stamped_) {
    stamped_->tick(ros::Time::now());
  } else {
    headerless_->tick();
  }
}

}  // namespace radio_follow
