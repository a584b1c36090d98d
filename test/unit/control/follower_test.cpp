// SPDX-License-Identifier: BSD-3-Clause
// The follower core with a law it has never seen: a toy law added through the FollowLaw
// interface alone (doc/architecture.md, "A new control law") gets the estimate, the track
// and the robot's pose, and whatever it asks for passes the safety verdict and the limits.
#include "radio_follow/control/follower.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {
namespace {

/// Turns towards the target and asks for a fixed, far too high speed: what comes out is
/// the pipeline's doing. Counts what the core calls.
class ToyLaw : public FollowLaw {
 public:
  LawOutput step(const FollowInput& input, double /*dt*/) override {
    ++steps;
    last = input;
    LawOutput out;
    out.command.linear = 10.0;
    out.command.angular = input.target ? input.target->bearing : 0.0;
    out.text = "Toy law.";
    return out;
  }
  void onStopped() override { ++stops; }
  bool addTrackPoint(const Eigen::Vector2d& point) override {
    ++points;
    return point.x() > 0.0;
  }
  void setCommon(const CommandPipelineParams& next) override {
    if (next.limits.max_linear > 1.0) {
      throw ParamError("~max_linear", "1.2", "at most 1 m/s for the toy law");
    }
  }

  int steps = 0;
  int stops = 0;
  int points = 0;
  FollowInput last;
};

CommandPipelineParams noRanges() {
  CommandPipelineParams params;
  params.safety.watch_ranges = false;  // the estimate alone decides
  return params;
}

/// The robot sees the target `range` m ahead along `bearing` at `t`.
EstimateUse hear(Follower& follower, double t, double range, double bearing,
                 TargetStatus status = TargetStatus::kOk) {
  return follower.onEstimate(t, t, status, range, bearing, PolarSpread{0.1, 0.02}, 1);
}

/// A follower running the toy law, enabled.
class FollowerTest : public ::testing::Test {
 protected:
  FollowerTest() : follower(noRanges()) {
    follower.setLaw(law);
    follower.pipeline().setEnabled(true);
  }
  ToyLaw law;
  Follower follower;
};

TEST_F(FollowerTest, RunsANewLawThroughTheInterfaceBehindTheSafetyLayer) {

  // No estimate yet: held, and the law is not asked.
  PipelineResult r = follower.tick(1.0, 0.05);
  EXPECT_FALSE(r.moving);
  EXPECT_EQ(r.state, FollowerState::kWaitingForTarget);
  EXPECT_EQ(law.steps, 0);
  EXPECT_EQ(law.stops, 1);

  EXPECT_EQ(hear(follower, 1.0, 3.0, 0.2), EstimateUse::kTrackPoint);
  const Pose2 robot{0.5, -0.5, 0.1};
  r = follower.tick(1.05, 0.05, robot);
  ASSERT_TRUE(r.moving);
  EXPECT_EQ(law.steps, 1);
  EXPECT_EQ(r.text, "Toy law.");
  ASSERT_TRUE(law.last.target.has_value());
  EXPECT_DOUBLE_EQ(law.last.target->range, 3.0);
  EXPECT_DOUBLE_EQ(law.last.target->bearing, 0.2);
  EXPECT_TRUE(law.last.target->range_valid);
  EXPECT_TRUE(std::isinf(law.last.target->module_gap));  // no ranges watched
  ASSERT_TRUE(law.last.robot.has_value());
  EXPECT_DOUBLE_EQ(law.last.robot->x, 0.5);
  EXPECT_DOUBLE_EQ(law.last.now, 1.05);
  // 10 m/s asked; the acceleration limit allows 0.5 m/s^2 * 0.05 s.
  EXPECT_NEAR(r.command.linear, 0.025, 1e-12);
  EXPECT_GT(r.command.angular, 0.0);

  // The estimate goes stale: the core stops the robot and tells the law.
  r = follower.tick(2.0, 0.05);
  EXPECT_FALSE(r.moving);
  EXPECT_EQ(r.command.linear, 0.0);
  EXPECT_EQ(law.steps, 1);
  EXPECT_EQ(law.stops, 2);
}

TEST_F(FollowerTest, RefusesAnEstimateFromTheFutureAndKeepsNothingOfIt) {
  hear(follower, 1.0, 3.0, 0.2);
  EXPECT_EQ(follower.onEstimate(1e9, 1.01, TargetStatus::kOk, 9.0, -1.0, PolarSpread{0.1, 0.02}, 1),
            EstimateUse::kRefused);
  const PipelineResult r = follower.tick(1.02, 0.05);
  EXPECT_FALSE(r.moving);
  EXPECT_EQ(law.steps, 0);
}

TEST_F(FollowerTest, TracksConfirmedPositionsAndGivesTheLawTheWalkingSpeed) {
  // A young track's DEGRADED estimate is no track point (TrackGate); HEADING_ONLY neither.
  EXPECT_EQ(hear(follower, 0.9, 3.0, 0.0, TargetStatus::kDegraded), EstimateUse::kHeard);
  EXPECT_EQ(hear(follower, 0.95, 3.0, 0.0, TargetStatus::kHeadingOnly), EstimateUse::kHeard);
  // The person walks along +x at about 1 m/s, the robot stands at the origin: the
  // locator's ground velocity is taken, nothing is differentiated.
  for (int i = 0; i <= 10; ++i) {
    const double t = 1.0 + 0.1 * i;
    ASSERT_EQ(hear(follower, t, 3.0 + 0.1 * i, 0.0), EstimateUse::kTrackPoint);
    const auto point = trackPoint(Eigen::Vector2d::Zero(), Eigen::Vector2d(3.0 + 0.1 * i, 0.0),
                                  Eigen::Vector2d(1.0 + 0.01 * i, 0.0));
    ASSERT_TRUE(point.has_value());
    EXPECT_TRUE(follower.addTrackPoint(t, *point));
  }
  EXPECT_EQ(law.points, 11);
  follower.tick(2.0, 0.05);
  ASSERT_TRUE(law.last.walking_speed.has_value());
  // The mean of the last second's velocities (TargetTrack::kWindow).
  EXPECT_NEAR(*law.last.walking_speed, 1.05, 1e-9);
  EXPECT_NEAR(law.last.target->receding_speed, 1.05, 1e-9);
  // A point older than the newest reaches neither the track nor the law.
  EXPECT_FALSE(follower.addTrackPoint(
      1.5,
      *trackPoint(Eigen::Vector2d::Zero(), Eigen::Vector2d(9.0, 0.0), Eigen::Vector2d(5.0, 0.0))));
  EXPECT_EQ(law.points, 11);
}

TEST_F(FollowerTest, NoFeedForwardWithoutTheLocatorsGroundVelocity) {
  // A position in odometry without a ground velocity yet (NaN in the message).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i <= 10; ++i) {
    const double t = 1.0 + 0.1 * i;
    ASSERT_EQ(hear(follower, t, 3.0 + 0.1 * i, 0.0), EstimateUse::kTrackPoint);
    const auto point = trackPoint(Eigen::Vector2d::Zero(), Eigen::Vector2d(3.0 + 0.1 * i, 0.0),
                                  Eigen::Vector2d(nan, nan));
    ASSERT_TRUE(point.has_value());
    EXPECT_TRUE(follower.addTrackPoint(t, *point));  // the path still grows
  }
  const PipelineResult r = follower.tick(2.0, 0.05);
  EXPECT_TRUE(r.moving);
  EXPECT_FALSE(law.last.walking_speed.has_value());
  EXPECT_EQ(law.last.target->receding_speed, 0.0);
}

TEST_F(FollowerTest, ALawRefusesCommonParametersBeforeThePipelineTakesThem) {
  CommandPipelineParams faster = noRanges();
  faster.limits.max_linear = 1.2;
  EXPECT_THROW(follower.setCommon(faster), ParamError);
  EXPECT_DOUBLE_EQ(follower.pipeline().params().limits.max_linear, MotionLimits().max_linear);
  CommandPipelineParams slower = noRanges();
  slower.limits.max_linear = 0.8;
  follower.setCommon(slower);
  EXPECT_DOUBLE_EQ(follower.pipeline().params().limits.max_linear, 0.8);
}

TEST(Follower, RefusesToTickWithoutALaw) {
  Follower follower(noRanges());
  EXPECT_THROW(follower.tick(1.0, 0.05), std::logic_error);
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
