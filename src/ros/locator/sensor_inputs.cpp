// SPDX-License-Identifier: BSD-3-Clause
// The one list of the locator's inputs: a new measurement kind adds its line here.
#include "radio_follow/AoaBearing.h"
#include "radio_follow/TdoaMeasurements.h"
#include "radio_follow/UwbRanges.h"
#include "radio_follow/ros/locator/sensor_input.hpp"

namespace radio_follow {

std::unique_ptr<SensorInput> makeUwbRangesInput(LocatorInputs& inputs);   // uwb_ranges_input.cpp
std::unique_ptr<SensorInput> makeAoaBearingInput(LocatorInputs& inputs);  // aoa_bearing_input.cpp
std::unique_ptr<SensorInput> makeTdoaInput(LocatorInputs& inputs);        // tdoa_input.cpp

const std::vector<SensorInputKind>& sensorInputKinds() {
  static const std::vector<SensorInputKind> kinds{
      sensorInputKind<UwbRanges>(makeUwbRangesInput),
      sensorInputKind<AoaBearing>(makeAoaBearingInput),
      sensorInputKind<TdoaMeasurements>(makeTdoaInput),
  };
  return kinds;
}

}  // namespace radio_follow
