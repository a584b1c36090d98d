// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/calibration_run.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/calibration_pairing.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

/// When the person stands at a point, recorded.
struct Stand {
  Eigen::Vector3d point;  ///< robot frame (the robot stands at the world origin), m
  double from;            ///< s, scenario time
  double until;
};

/// The person's walk through every point and the windows in which each is recorded.
sim::Scenario calibrationWalk(const CalibrationRunParams& p, std::vector<Stand>& stands) {
  sim::Scenario scenario;
  scenario.name = "calibration_run";
  scenario.target_height = p.tag_height;
  scenario.target_accel = 0.0;
  bool first = true;
  for (const double distance : p.distances) {
    for (int k = 0; k < p.directions; ++k) {
      const double angle = 2.0 * kPi * k / p.directions;
      const double x = distance * std::cos(angle);
      const double y = distance * std::sin(angle);
      if (first) {
        scenario.target = sim::TargetPath(Pose2{x, y, 0.0});
        first = false;
      } else {
        scenario.target.walkTo(x, y, p.walk_speed);
      }
      const double arrival = scenario.target.duration();
      scenario.target.wait(p.settle + p.dwell);
      stands.push_back(Stand{Eigen::Vector3d(x, y, p.tag_height), arrival + p.settle,
                             arrival + p.settle + p.dwell});
    }
  }
  scenario.duration = scenario.target.duration();
  return scenario;
}

const Stand* standAt(const std::vector<Stand>& stands, double t) {
  for (const Stand& s : stands) {
    if (t >= s.from && t <= s.until) {
      return &s;
    }
  }
  return nullptr;
}

}  // namespace

void CalibrationRunParams::validate() const {
  require(!distances.empty(), "calibration distances", distances.size(), "at least one distance");
  for (const double d : distances) {
    require(std::isfinite(d) && d > 0.0, "calibration distance", d, "metres > 0");
  }
  require(directions >= 1, "calibration directions", directions, "at least 1");
  require(std::isfinite(dwell) && dwell > 0.0, "calibration dwell", dwell, "seconds > 0");
  require(std::isfinite(settle) && settle >= 0.0, "calibration settle", settle, "seconds >= 0");
  require(std::isfinite(walk_speed) && walk_speed > 0.0, "calibration walk_speed", walk_speed,
          "m/s > 0");
  require(std::isfinite(aoa_max_azimuth) && aoa_max_azimuth > 0.0 && aoa_max_azimuth < kPi / 2.0,
          "calibration aoa_max_azimuth", aoa_max_azimuth, "an angle in (0, pi/2) rad");
  require(range_degree >= 0 && range_degree <= 3, "calibration range_degree", range_degree,
          "0 to 3");
}

CalibrationResult runCalibration(const Layout& layout, const sim::WorldConfig& world,
                                 const CalibrationRunParams& params) {
  params.validate();
  std::vector<Stand> stands;
  const sim::Scenario scenario = calibrationWalk(params, stands);
  sim::World sim_world(layout, scenario, world);
  std::vector<std::vector<estimation::RangeSample>> ranges(layout.twr_modules.size());
  std::vector<std::vector<estimation::AzimuthSample>> azimuths(layout.aoa_boards.size());
  std::vector<std::vector<estimation::ElevationSample>> elevations(layout.aoa_boards.size());
  while (!sim_world.finished()) {
    const sim::StepEvents events = sim_world.step(0.0, 0.0, 0.01);  // the robot stands
    for (const sim::TwrEvent& e : events.twr) {
      if (const Stand* s = standAt(stands, e.t)) {
        // The truth is the tape: the module where the layout says it is.
        const double truth = (s->point - layout.twr_modules[e.module].position).norm();
        ranges[e.module].push_back({e.range, truth});
      }
    }
    for (const sim::AoaEvent& e : events.aoa) {
      const Stand* s = standAt(stands, e.t);
      if (!s) {
        continue;
      }
      const AoaBoard& board = layout.aoa_boards[e.board];
      const Eigen::Vector3d local = board.orientation.conjugate() * (s->point - board.position);
      const double truth = std::atan2(local.y(), local.x());
      // Points well inside the board's hemisphere only: behind it, or at its edges, the
      // bearing says nothing about how the board is mounted.
      if (local.x() > 0.0 && std::abs(truth) <= params.aoa_max_azimuth) {
        azimuths[e.board].push_back({e.sample.azimuth, truth});
        elevations[e.board].push_back(
            {e.sample.elevation, estimation::trueElevation(board, s->point)});
      }
    }
  }

  CalibrationResult result;
  result.layout = layout;
  for (std::size_t i = 0; i < layout.twr_modules.size(); ++i) {
    TwrModule& module = result.layout.twr_modules[i];
    const estimation::RangeCalibrationFit fit =
        estimation::fitRangeCalibration(ranges[i], params.range_degree);
    module.calibration = fit.coefficients;
    result.modules.push_back({module.id, fit});
  }
  for (std::size_t i = 0; i < layout.aoa_boards.size(); ++i) {
    AoaBoard& board = result.layout.aoa_boards[i];
    const estimation::YawOffsetFit fit = estimation::fitYawOffset(azimuths[i]);
    board.orientation =
        board.orientation * Eigen::AngleAxisd(fit.yaw_offset, Eigen::Vector3d::UnitZ());
    const estimation::ElevationOffsetFit elevation = estimation::fitElevationOffset(elevations[i]);
    board.elevation_offset = elevation.elevation_offset;
    result.boards.push_back({board.id, fit, elevation});
  }
  return result;
}

Layout locatorLayoutFor(const Layout& layout, const sim::WorldConfig& world) {
  Layout calibrated = runCalibration(layout, world).layout;
  if (world.profile == sim::SensorProfile::kIdeal) {
    // Ideal boards sit exactly as designed: a yaw fit would only turn them by the tables'
    // direction-dependent azimuth bias (lab locator_cold_starts --sensor-profile ideal: NEES
    // 18.6 with it, 3.2 without).
    calibrated.aoa_boards = layout.aoa_boards;
  }
  return calibrated;
}

LayoutCalibrationUpdate CalibrationResult::update() const {
  LayoutCalibrationUpdate u;
  for (const ModuleCalibration& m : modules) {
    u.range_calibration[m.id] = m.fit.coefficients;
  }
  for (const BoardCalibration& b : boards) {
    u.yaw_offset[b.id] = b.fit.yaw_offset;
    u.elevation_offset[b.id] = b.elevation.elevation_offset;
  }
  return u;
}

}  // namespace evaluation
}  // namespace radio_follow
