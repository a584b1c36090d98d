// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// For locator unit tests that feed exact (true) ranges: the shipped layouts without their
// modules' range calibration, and a helper that ranges every module to a point.

#include <gtest/gtest.h>

#include <string>

#include "radio_follow/estimation/locator.hpp"

namespace radio_follow::test {

/// config/layouts/<name> with every module's calibration set to the identity.
inline Layout uncalibratedLayout(const std::string& name) {
  Layout layout = loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/" + name);
  for (auto& m : layout.twr_modules) {
    m.calibration = {0.0, 1.0};
  }
  return layout;
}

/// The default tuning with the solver estimator (Ceres per update + Kalman filter): the
/// tests of that estimator's own behaviour (the mirror test, board selection, gating).
inline estimation::LocatorConfig solverBackend() {
  estimation::LocatorConfig config;
  config.estimator = estimation::Estimator::kSolver;
  config.range_sigma = 0.03;  // the tuning these tests were written for
  config.process_noise = 1.0;
  return config;
}

/// Every module of the locator's layout reports its exact range to `truth` at time t.
inline void feedRanges(estimation::Locator& locator, const Eigen::Vector3d& truth, double t) {
  const auto& modules = locator.layout().twr_modules;
  for (std::size_t i = 0; i < modules.size(); ++i) {
    ASSERT_TRUE(locator.addRange(i, (truth - modules[i].position).norm(), t));
  }
}

}  // namespace radio_follow::test
