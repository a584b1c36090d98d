// SPDX-License-Identifier: BSD-3-Clause
// The one list of the locator's inputs: a new measurement kind adds its line here.
#include "radio_follow/ros/locator/sensor_input.hpp"

namespace radio_follow {

std::unique_ptr<SensorInput> makeUwbRangesInput(LocatorInputs& inputs);   // uwb_ranges_input.cpp
std::unique_ptr<SensorInput> makeAoaBearingInput(LocatorInputs& inputs);  // aoa_bearing_input.cpp
std::unique_ptr<SensorInput> makeTdoaInput(LocatorInputs& inputs);        // tdoa_input.cpp

std::vector<std::unique_ptr<SensorInput>> makeSensorInputs(LocatorInputs& inputs) {
  std::vector<std::unique_ptr<SensorInput>> all;
  for (const auto make : {makeUwbRangesInput, makeAoaBearingInput, makeTdoaInput}) {
    all.push_back(make(inputs));
  }
  return all;
}

}  // namespace radio_follow
