// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/locator/locator_reconfigure.hpp"

#include <string>
#include <utility>

#include "radio_follow/ros/common/reconfigure_table.hpp"

namespace radio_follow {

// The mapping follows from the parameter table by name (ros/common/reconfigure_table.hpp).
LocatorTuningConfig toTuning(const estimation::LocatorConfig& c) {
  return tuningFromTable<LocatorTuningConfig>(estimation::LocatorConfig::table(), c);
}

estimation::LocatorConfig fromTuning(const LocatorTuningConfig& t, estimation::LocatorConfig c) {
  return tableFromTuning(estimation::LocatorConfig::table(), t, std::move(c));
}

std::unique_ptr<LocatorReconfigure> makeLocatorReconfigure(
    const ros::NodeHandle& private_nh, const estimation::LocatorConfig& initial,
    std::function<void(const estimation::LocatorConfig&)> apply) {
  return std::make_unique<LocatorReconfigure>(private_nh, initial, toTuning, fromTuning,
                                              std::move(apply));
}

}  // namespace radio_follow
