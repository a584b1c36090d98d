// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/config/layout_writer.hpp"
#include "radio_follow/estimation/calibration_fit.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {
namespace evaluation {

/// How the simulated calibration run is done: the robot stands at the origin, the person
/// stands at tape-measured points (every distance in every direction) for a while each.
struct CalibrationRunParams {
  std::vector<double> distances{1.0, 2.0, 3.0, 4.0, 6.0, 8.0};  ///< m from the robot's origin
  int directions = 8;             ///< evenly spaced around the robot, the first straight ahead
  double dwell = 3.0;             ///< s recorded at each point
  double settle = 0.5;            ///< s standing before recording starts
  double walk_speed = 1.2;        ///< m/s between points (nothing recorded while walking)
  double tag_height = kDefaultTargetHeight;  ///< m, tape-measured like the points
  double aoa_max_azimuth = 0.87;  ///< rad (50 deg): points a board sees farther off are unused
  int range_degree = 1;           ///< of each module's calibration polynomial

  /// Throws ParamError naming the first unusable field.
  void validate() const;
};

/// One module's or board's fit, by ID.
struct ModuleCalibration {
  std::string id;
  estimation::RangeCalibrationFit fit;
};
struct BoardCalibration {
  std::string id;
  estimation::YawOffsetFit fit;
  estimation::ElevationOffsetFit elevation;
};

struct CalibrationResult {
  /// The input layout with every module's calibration and every board's yaw and
  /// elevation offset from the fits.
  Layout layout;
  std::vector<ModuleCalibration> modules;
  std::vector<BoardCalibration> boards;

  /// The fits as an update of the layout's file (config/layout_writer.hpp).
  LayoutCalibrationUpdate update() const;
};

/// Calibrates `layout` as one would a real robot: the simulated sensors (`world`: profile,
/// hardware and noise seeds) report while the person stands at the points of `params`,
/// and each module's (raw range, tape-measured distance) pairs go through
/// estimation::fitRangeCalibration, each board's (azimuth, tape-measured azimuth) pairs
/// through estimation::fitYawOffset and its elevations through fitElevationOffset. It sees
/// only the sensors' output and the points, never the simulator's error model. Throws
/// ParamError on bad parameters and std::invalid_argument when a sensor gave too few
/// samples to fit.
CalibrationResult runCalibration(const Layout& layout, const sim::WorldConfig& world,
                                 const CalibrationRunParams& params = {});

/// The layout a locator should be given for a run on `world`'s simulated robot: the
/// calibration run's, whatever the profile (the ideal modules err by thesis Table 3.1, the
/// realistic ones by their hardware; a layout file's calibration is some other robot's:
/// the shipped ones are the ROS simulator's, realistic with hardware_seed 1). Ideal boards
/// keep the layout's orientation: they have no mounting error to find.
Layout locatorLayoutFor(const Layout& layout, const sim::WorldConfig& world);

}  // namespace evaluation
}  // namespace radio_follow
