// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/locator/locator_inputs.hpp"

#include <cmath>

namespace radio_follow {
namespace {

std::vector<std::unique_ptr<SensorInput>> makeInputs(LocatorInputs& inputs) {
  std::vector<std::unique_ptr<SensorInput>> all;
  for (const SensorInputKind& kind : sensorInputKinds()) {
    all.push_back(kind.make(inputs));
  }
  return all;
}

}  // namespace

LocatorInputs::LocatorInputs(estimation::Locator& locator)
    : locator_(locator), inputs_(makeInputs(*this)) {}

LocatorInputs::LocatorInputs(estimation::Locator& locator, PoseLookup lookup, Clock clock)
    : locator_(locator),
      lookup_(std::move(lookup)),
      clock_(std::move(clock)),
      inputs_(makeInputs(*this)) {}

bool LocatorInputs::poseFor(const ros::Time& stamp, std::optional<Pose2>* pose) {
  pose->reset();
  if (!lookup_) {
    return true;
  }
  // A stamp further than kTfHorizon from the receiver's clock has no transform in any TF
  // buffer (tf2 keeps 10 s): the lookup's answer is known, nothing, and asking tf2 about a
  // stamp 2^32 s away overflows ros::Duration in its error text (issue 34).
  const double age = clock_() - stamp.toSec();
  if (std::abs(age) <= kTfHorizon) {
    *pose = lookup_(stamp);
  }
  const auto decision = placement_.decide(*pose, clock_());
  if (decision == estimation::OdometryPlacement::Decision::kRobotFrame) {
    pose->reset();
  }
  return decision != estimation::OdometryPlacement::Decision::kDrop;
}

}  // namespace radio_follow
