// SPDX-License-Identifier: BSD-3-Clause
// The simulated calibration run (evaluation/calibration_run.hpp): on realistic sensors the
// calibrated layout removes most of each module's bias and each board's mounting error.
#include "radio_follow/evaluation/calibration_run.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

Layout spot() {
  return loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/spot.yaml");
}

sim::WorldConfig realistic(std::uint64_t hardware_seed) {
  sim::WorldConfig w;
  w.profile = sim::SensorProfile::kRealistic;
  w.hardware_seed = hardware_seed;
  return w;
}

double yawOf(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d r = q.toRotationMatrix();
  return std::atan2(r(1, 0), r(0, 0));
}

/// The range bias a calibration polynomial can remove: each module's mean error at a
/// distance, averaged over eight directions (the bearing dependence averages out), then
/// |.| averaged over modules and distances; raw and with the calibrated layout's
/// polynomials, at check points other than the calibration's, on fresh noise seeds of the
/// same hardware.
std::pair<double, double> biasBeforeAfter(const Layout& calibrated, std::uint64_t hardware_seed) {
  const Layout layout = spot();
  const std::size_t modules = layout.twr_modules.size();
  double before = 0.0;
  double after = 0.0;
  int cells = 0;
  for (const double distance : {1.5, 2.5, 5.0, 7.0}) {
    std::vector<double> raw(modules, 0.0);
    std::vector<double> corrected(modules, 0.0);
    std::vector<int> n(modules, 0);
    for (int k = 0; k < 8; ++k) {
      const double angle = kPi / 8.0 + 2.0 * kPi * k / 8.0;
      sim::Scenario s;
      s.target = sim::TargetPath(Pose2{distance * std::cos(angle), distance * std::sin(angle), 0});
      s.duration = 20.0;
      sim::WorldConfig w = realistic(hardware_seed);
      w.seed = 100 + static_cast<std::uint64_t>(k);
      sim::World world(layout, s, w);
      const Eigen::Vector3d point = world.targetInRobot();
      while (!world.finished()) {
        for (const sim::TwrEvent& e : world.step(0.0, 0.0, 0.01).twr) {
          const double truth = (point - layout.twr_modules[e.module].position).norm();
          raw[e.module] += e.range - truth;
          corrected[e.module] += calibrated.twr_modules[e.module].correctRange(e.range) - truth;
          ++n[e.module];
        }
      }
    }
    for (std::size_t i = 0; i < modules; ++i) {
      before += std::abs(raw[i] / n[i]);
      after += std::abs(corrected[i] / n[i]);
      ++cells;
    }
  }
  return {before / cells, after / cells};
}

TEST(CalibrationRun, RemovesMostOfTheRangeBiasAndTheMountingError) {
  for (std::uint64_t hardware = 1; hardware <= 3; ++hardware) {
    const CalibrationResult result = runCalibration(spot(), realistic(hardware));
    ASSERT_EQ(result.modules.size(), 3u);
    const auto [before, after] = biasBeforeAfter(result.layout, hardware);
    std::printf("hardware %d: mean |range bias| %.3f m raw, %.3f m calibrated\n",
                static_cast<int>(hardware), before, after);
    EXPECT_GT(before, 0.15) << "the realistic modules read long";
    EXPECT_LT(after, 0.2 * before);
    EXPECT_LT(after, 0.03);
    const Layout layout = spot();
    for (std::size_t i = 0; i < result.boards.size(); ++i) {
      const AoaBoard& designed = layout.aoa_boards[i];
      // The test may look at the hardware; the calibration run never does. A board's
      // azimuth bias (it reports bias + the true azimuth in its mounted frame) is a yaw
      // offset to the calibration like the mounting's.
      const double mounting =
          wrapAngle(yawOf(sim::mountedAoaBoard(designed, hardware).orientation) -
                    yawOf(designed.orientation));
      const double bias = sim::AoaErrorState(designed, hardware).azimuthBias();
      const double left = wrapAngle(mounting - bias - result.boards[i].fit.yaw_offset);
      std::printf("hardware %d, board %s: mounted %+.2f deg, bias %+.2f deg, fitted %+.2f deg\n",
                  static_cast<int>(hardware), designed.id.c_str(), rad2deg(mounting), rad2deg(bias),
                  rad2deg(result.boards[i].fit.yaw_offset));
      // What is left: a real board's slowly varying error (6 deg) holds still while the
      // person stands at a tape point, so each of the ~18 points a board sees within 50 deg
      // of its boresight is one draw of it (the mean's sigma 1.4 deg), and the tables' edge
      // biases; 3.5 sigma.
      EXPECT_LT(std::abs(left), deg2rad(5.0)) << designed.id;
      // A real board reads its elevation 2-11 deg low (issue 35); the fit finds that bias
      // from the sensors' output. Shadowed readings (3 %, 5-35 deg high) are refused. The
      // fit also holds the thesis tables' direction-dependent elevation bias averaged over
      // the points the board sees (the same per board position on every robot: up to
      // 2.4 deg here), which is its due: the board reports it in that geometry.
      const double elevation_bias = sim::AoaErrorState(designed, hardware).elevationBias();
      std::printf("  elevation bias %+.2f deg, fitted %+.2f deg\n", rad2deg(elevation_bias),
                  rad2deg(result.boards[i].elevation.elevation_offset));
      EXPECT_NEAR(result.boards[i].elevation.elevation_offset, elevation_bias, deg2rad(3.0))
          << designed.id;
      EXPECT_EQ(result.layout.aoa_boards[i].elevation_offset,
                result.boards[i].elevation.elevation_offset);
    }
  }
}

TEST(CalibrationRun, IsDeterministicAndCalibratesTheIdealSensorsToo) {
  const Layout a = runCalibration(spot(), realistic(4)).layout;
  const Layout b = runCalibration(spot(), realistic(4)).layout;
  for (std::size_t i = 0; i < a.twr_modules.size(); ++i) {
    EXPECT_EQ(a.twr_modules[i].calibration, b.twr_modules[i].calibration);
  }
  EXPECT_TRUE(a.aoa_boards[0].orientation.isApprox(b.aoa_boards[0].orientation, 0.0));
  // The ideal sensors read short by Table 3.1's bias (0.06-0.26 m over 1-12 m): their own
  // fit adds to the range (the shipped layouts' calibration, the realistic robot 1's, takes
  // off: a layout file's calibration is not what the locator of a simulated run gets).
  sim::WorldConfig ideal;
  ideal.profile = sim::SensorProfile::kIdeal;
  const Layout fitted = locatorLayoutFor(spot(), ideal);
  for (std::size_t i = 0; i < fitted.twr_modules.size(); ++i) {
    const std::vector<double>& c = fitted.twr_modules[i].calibration;
    ASSERT_EQ(c.size(), 2u);
    const double at_3m = c[0] + 3.0 * c[1] - 3.0;
    EXPECT_GT(at_3m, 0.05) << fitted.twr_modules[i].id;
    EXPECT_LT(at_3m, 0.3) << fitted.twr_modules[i].id;
  }
  // Ideal boards are mounted as designed: nothing to turn.
  for (std::size_t i = 0; i < fitted.aoa_boards.size(); ++i) {
    EXPECT_TRUE(fitted.aoa_boards[i].orientation.isApprox(spot().aoa_boards[i].orientation, 0.0))
        << fitted.aoa_boards[i].id;
  }
  EXPECT_NE(locatorLayoutFor(spot(), realistic(4)).twr_modules[0].calibration,
            spot().twr_modules[0].calibration);
}

TEST(CalibrationRun, ItsUpdateWritesTheCalibratedLayout) {
  const CalibrationResult result = runCalibration(spot(), realistic(1));
  std::ifstream in(std::string(RF_CONFIG_DIR) + "/layouts/spot.yaml");
  std::stringstream text;
  text << in.rdbuf();
  const Layout back =
      parseLayout(writeCalibratedLayout(text.str(), "spot.yaml", result.update(), {}), "written");
  for (std::size_t i = 0; i < back.twr_modules.size(); ++i) {
    for (std::size_t k = 0; k < back.twr_modules[i].calibration.size(); ++k) {
      EXPECT_NEAR(back.twr_modules[i].calibration[k], result.layout.twr_modules[i].calibration[k],
                  1e-5);  // written with 6 significant digits
    }
  }
  for (std::size_t i = 0; i < back.aoa_boards.size(); ++i) {
    EXPECT_NEAR(yawOf(back.aoa_boards[i].orientation),
                yawOf(result.layout.aoa_boards[i].orientation), 1e-4);
    EXPECT_NE(back.aoa_boards[i].elevation_offset, 0.0);
    EXPECT_NEAR(back.aoa_boards[i].elevation_offset, result.layout.aoa_boards[i].elevation_offset,
                1e-5);
  }
}

TEST(CalibrationRun, RefusesBadParametersNamingThem) {
  CalibrationRunParams p;
  p.dwell = 0.0;
  try {
    runCalibration(spot(), realistic(1), p);
    FAIL() << "accepted a zero dwell";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "calibration dwell");
  }
  p = CalibrationRunParams{};
  p.distances = {3.0};  // one distance cannot fix a scale
  EXPECT_THROW(runCalibration(spot(), realistic(1), p), std::invalid_argument);
}

}  // namespace
}  // namespace evaluation
}  // namespace radio_follow
