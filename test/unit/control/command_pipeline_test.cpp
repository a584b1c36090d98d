// SPDX-License-Identifier: BSD-3-Clause
// The command pipeline's guard on the layout's range calibrations (the safety stop corrects
// raw ranges with them): the shipped layouts and the largest correction a real module
// needs pass, a typo-sized shift or slope stops the controller at start, naming the module.
#include "radio_follow/control/command_pipeline.hpp"

#include <gtest/gtest.h>

#include <limits>
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

// Issue 34, defect 3: the drivers' bounds hold in the safety path. A range no module can
// report (inf, 1e300, NaN, negative, beyond kMaxUwbRange) stops the robot, never keeps the
// range watchdog alive, and is named when it is all that arrives.
TEST(CommandPipeline, ImplausibleRangesStopAndAreNoLiveRanges) {
  for (const double bad : {std::numeric_limits<double>::infinity(), 1e300, 300.5,
                           std::numeric_limits<double>::quiet_NaN(), -1.0}) {
    CommandPipelineParams params;
    params.safety.watch_ranges = true;
    CommandPipeline pipeline(params);
    pipeline.setEnabled(true);
    pipeline.onRange(0.0, 0.0, "t/5722", "5722", "", 4.0);
    pipeline.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
    ASSERT_TRUE(pipeline.check(0.1).may_move) << bad;
    EXPECT_TRUE(pipeline.onRange(0.2, 0.2, "t/5722", "5722", "", bad)) << bad;
    EXPECT_FALSE(pipeline.check(0.2).may_move) << bad;
    // Only implausible ranges from now on, fresh estimates: never moves again.
    for (double t = 0.3; t < 5.0; t += 0.1) {
      pipeline.onRange(t, t, "t/5722", "5722", "", bad);
      pipeline.onEstimate(t, t, EstimateQuality::kUsable);
      const SafetyDecision d = pipeline.check(t);
      ASSERT_FALSE(d.may_move) << bad << " at " << t;
      if (t > 1.5) {
        EXPECT_EQ(d.reason, StopReason::kImplausibleRange) << bad << " at " << t;
      }
    }
    EXPECT_GT(pipeline.monitor().implausibleRanges(), 40u);
  }
}

// A callback that threw (the node's CallbackBarrier) blocks motion for hold_time.
TEST(CommandPipeline, AFaultBlocksMotionForHoldTime) {
  CommandPipelineParams params;
  params.safety.watch_ranges = false;
  CommandPipeline pipeline(params);
  pipeline.setEnabled(true);
  pipeline.onEstimate(0.0, 0.0, EstimateQuality::kUsable);
  ASSERT_TRUE(pipeline.check(0.05).may_move);
  pipeline.onFault(0.1);
  pipeline.onEstimate(0.2, 0.2, EstimateQuality::kUsable);
  const SafetyDecision d = pipeline.check(0.2);
  EXPECT_FALSE(d.may_move);
  EXPECT_EQ(d.reason, StopReason::kInternalFault);
  pipeline.onEstimate(1.15, 1.15, EstimateQuality::kUsable);
  EXPECT_TRUE(pipeline.check(1.15).may_move);  // hold_time 1 s after the fault
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
