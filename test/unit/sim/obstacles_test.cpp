// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/obstacles.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/sim/target_path.hpp"

namespace radio_follow {
namespace sim {
namespace {

TEST(Obstacles, RayHitsTheNearestCircleOrWall) {
  Obstacles o;
  o.circles.push_back(CircleObstacle{3.0, 0.0, 0.5});
  o.walls.push_back(WallObstacle{5.0, -1.0, 5.0, 1.0});
  o.walls.push_back(WallObstacle{-2.0, -5.0, -2.0, 5.0});
  EXPECT_NEAR(castRay(o, 0, 0, 0.0), 2.5, 1e-12);
  EXPECT_NEAR(castRay(o, 0, 0, kPi), 2.0, 1e-12);
  EXPECT_TRUE(std::isinf(castRay(o, 0, 0, kPi / 2.0)));
  // Past the circle's side (0.53 m from its centre): the wall at x = 5, y = 0.9.
  EXPECT_NEAR(castRay(o, 0, 0, std::atan2(0.9, 5.0)), std::hypot(5.0, 0.9), 1e-9);
  // From inside a circle the ray touches it at once.
  EXPECT_DOUBLE_EQ(castRay(o, 3.0, 0.0, 1.0), 0.0);
}

TEST(Obstacles, ScanIsInTheRobotFrameAndCutAtRangeMax) {
  Obstacles o;
  o.circles.push_back(CircleObstacle{0.0, 2.0, 0.2});  // 2 m to the world's +y
  ScanConfig config;
  config.beams = 3;
  config.angle_min = -kPi / 2.0;
  config.angle_max = kPi / 2.0;
  config.range_max = 5.0;
  // Robot faces +y: the obstacle is straight ahead (middle beam).
  const auto ranges = scanRanges(o, config, Pose2{0, 0, kPi / 2.0});
  ASSERT_EQ(ranges.size(), 3u);
  EXPECT_NEAR(ranges[1], 1.8, 1e-9);
  EXPECT_TRUE(std::isinf(ranges[0]));
  EXPECT_TRUE(std::isinf(ranges[2]));
  config.range_max = 1.0;
  EXPECT_TRUE(std::isinf(scanRanges(o, config, Pose2{0, 0, kPi / 2.0})[1]));
}

TEST(Obstacles, ClearanceToCirclesAndWalls) {
  Obstacles o;
  o.circles.push_back(CircleObstacle{3.0, 0.0, 0.5});
  o.walls.push_back(WallObstacle{0.0, 2.0, 4.0, 2.0});
  EXPECT_NEAR(clearance(o, 0.0, 0.0), 2.0, 1e-12);
  EXPECT_NEAR(clearance(o, 3.0, 1.0), 0.5, 1e-12);
  EXPECT_NEAR(clearance(o, 6.0, 2.0), 2.0, 1e-12);
}

TEST(Obstacles, ScenarioReadsObstaclesAndRejectsBadOnes) {
  const Scenario s = parseScenario(
      "target: {start: [5, 0]}\nobstacles: {circles: [[2, 0, 0.3]], walls: [[0, 1, 4, 1]]}", "test",
      1);
  ASSERT_EQ(s.obstacles.circles.size(), 1u);
  ASSERT_EQ(s.obstacles.walls.size(), 1u);
  EXPECT_DOUBLE_EQ(s.obstacles.circles[0].radius, 0.3);
  // Either list may be absent.
  EXPECT_EQ(parseScenario("target: {start: [5, 0]}\nobstacles: {circles: [[2, 0, 1]]}", "test", 1)
                .obstacles.walls.size(),
            0u);
  try {
    parseScenario("target: {start: [5, 0]}\nobstacles: {circles: [[2, 0]]}", "test", 1);
    FAIL();
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "obstacles.circles[0]");
  }
}

TEST(Obstacles, ScanConfigValidation) {
  ScanConfig config;
  config.beams = 1;
  EXPECT_THROW(config.validate(), ParamError);
}

}  // namespace
}  // namespace sim
}  // namespace radio_follow
