// SPDX-License-Identifier: BSD-3-Clause
// The command pipeline's guard on the layout's range calibrations (the safety stop corrects
// raw ranges with them): the shipped layouts and the largest correction a real module
// needs pass, a typo-sized shift or slope stops the controller at start, naming the module.
#include "radio_follow/control/command_pipeline.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/config/layout.hpp"

namespace radio_follow {
namespace control {
namespace {

CommandPipelineParams withModule(const std::vector<double>& calibration) {
  CommandPipelineParams params;
  TwrModule module;
  module.id = "5722";
  module.calibration = calibration;
  params.calibrated_modules[module.id] = module;
  return params;
}

TEST(CommandPipelineParams, AcceptsEveryShippedLayoutsCalibration) {
  for (const char* name : {"spot", "spot_twr", "tracked", "cube"}) {
    const Layout layout = loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/" + name + ".yaml");
    CommandPipelineParams params;
    for (const TwrModule& m : layout.twr_modules) {
      params.calibrated_modules[m.id] = m;
    }
    EXPECT_NO_THROW(params.validate()) << name;
  }
}

TEST(CommandPipelineParams, AcceptsARealModulesBiasAndRefusesATypo) {
  // The longest-reading module of issue 14's recording: +0.31 m and +2 % of the range.
  EXPECT_NO_THROW(withModule({-0.31 / 1.02, 1.0 / 1.02}).validate());
  EXPECT_NO_THROW(withModule({0.2, 1.0}).validate());
  for (const std::vector<double>& typo :
       {std::vector<double>{0.6, 1.0}, std::vector<double>{-0.6, 1.0},
        std::vector<double>{0.0, 3.0}, std::vector<double>{1.3, -0.01}}) {
    try {
      withModule(typo).validate();
      ADD_FAILURE() << "accepted calibration [" << typo[0] << ", " << typo[1] << "]";
    } catch (const ParamError& e) {
      EXPECT_EQ(e.name(), "~layout_file twr_modules[5722].calibration");
    }
  }
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
