// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/velocity_law.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {
namespace {

TargetPolar target(double range, double bearing) {
  TargetPolar t;
  t.range = range;
  t.bearing = bearing;
  return t;
}

TEST(VelocityLaw, DrivesForwardWhenTargetAheadAndFar) {
  VelocityLaw law{VelocityLawParams()};
  const VelocityCommand cmd = law.update(target(4.0, 0.0), 0.05);
  EXPECT_GT(cmd.linear, 0.5);
  EXPECT_NEAR(cmd.angular, 0.0, 1e-12);
  EXPECT_FALSE(law.arrived());
}

TEST(VelocityLaw, NeverBacksAwayWhenTooClose) {
  VelocityLaw law{VelocityLawParams()};
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(law.update(target(1.0, 0.0), 0.05).linear, 0.0);
  }
  EXPECT_TRUE(law.arrived());
}

TEST(VelocityLaw, SlowsDownAsGapCloses) {
  VelocityLaw far_law{VelocityLawParams()};
  VelocityLaw near_law{VelocityLawParams()};
  const double far = far_law.update(target(3.0, 0.0), 0.05).linear;
  const double near = near_law.update(target(1.8, 0.0), 0.05).linear;
  EXPECT_GT(far, near);
  EXPECT_LE(near, slowdownCap(0.2, 1.0, 0.2, 1.0) + 1e-12);
}

TEST(SlowdownCap, PassesThroughTheTargetSpeedAtTheFollowDistance) {
  // slowdown 0.3 m beyond, closing 0.2 m inside, max 1.5 m/s.
  EXPECT_EQ(slowdownCap(0.0, 0.3, 0.2, 1.5, 1.0), 1.0);
  EXPECT_NEAR(slowdownCap(1e-9, 0.3, 0.2, 1.5, 1.0), 1.0, 1e-6);    // continuous from above
  EXPECT_NEAR(slowdownCap(-1e-9, 0.3, 0.2, 1.5, 1.0), 1.0, 1e-6);   // and from below
  EXPECT_NEAR(slowdownCap(0.15, 0.3, 0.2, 1.5, 1.0), 1.25, 1e-12);  // 1 + 0.5 * 0.5
  EXPECT_EQ(slowdownCap(0.3, 0.3, 0.2, 1.5, 1.0), 1.5);
  EXPECT_EQ(slowdownCap(5.0, 0.3, 0.2, 1.5, 1.0), 1.5);
  EXPECT_NEAR(slowdownCap(-0.1, 0.3, 0.2, 1.5, 1.0), 0.5, 1e-12);  // halfway in: half speed
  EXPECT_EQ(slowdownCap(-0.2, 0.3, 0.2, 1.5, 1.0), 0.0);           // stopped 0.2 m inside
  EXPECT_EQ(slowdownCap(-1.0, 0.3, 0.2, 1.5, 1.0), 0.0);
}

TEST(SlowdownCap, AStandingPersonIsNeverApproachedInsideTheFollowDistance) {
  EXPECT_EQ(slowdownCap(0.0, 0.3, 0.2, 1.5, 0.0), 0.0);
  EXPECT_EQ(slowdownCap(-0.1, 0.3, 0.2, 1.5, 0.0), 0.0);
  EXPECT_NEAR(slowdownCap(0.06, 0.3, 0.2, 1.5, 0.0), 0.3, 1e-12);   // 1.5 * 0.2
  EXPECT_NEAR(slowdownCap(0.06, 0.3, 0.2, 1.5, -1.0), 0.3, 1e-12);  // walking towards: as 0
  EXPECT_EQ(slowdownCap(-0.1, 0.3, 0.2, 1.5, -1.0), 0.0);
  EXPECT_EQ(slowdownCap(std::nan(""), 0.3, 0.2, 1.5, 1.0), 0.0);
  // A target speed above the robot's own cannot lift the cap above max_speed.
  EXPECT_EQ(slowdownCap(0.0, 0.3, 0.2, 1.5, 3.0), 1.5);
}

TEST(VelocityLaw, FeedForwardHoldsAWalkingPersonAtTheFollowDistance) {
  // A person walking away at 1 m/s, a robot that tracks its command, P only: with the
  // feed-forward the gap settles at the follow distance (the cap lets the robot match the
  // person's speed there), plus what braking from 1 m/s needs beyond the closing distance
  // (1 x 0.05 + 1 / (2 x 2) - 0.2 = 0.1 m: the person may stop at any step); without it the
  // law cannot keep up.
  VelocityLawParams p;
  p.max_linear = 1.5;
  p.slowdown_distance = 0.3;
  p.linear = PidGains{1.0, 0.0, 0.0, 0.3, 0.2, 1.5};
  for (const double feed_forward : {1.0, 0.0}) {
    p.feed_forward = feed_forward;
    VelocityLaw law{p};
    double range = 3.0;
    for (int i = 0; i < 1200; ++i) {
      TargetPolar t = target(range, 0.0);
      t.receding_speed = 1.0;
      range += (1.0 - law.update(t, 0.05).linear) * 0.05;
    }
    if (feed_forward > 0.0) {
      EXPECT_NEAR(range, p.follow_distance + 0.1, 0.01);
    } else {
      EXPECT_GT(range, p.follow_distance + 0.3);
    }
  }
}

TEST(VelocityLaw, InsideTheFollowDistanceSpeedFallsToZeroOverTheClosingDistance) {
  VelocityLawParams p;
  const double d = p.follow_distance;
  for (const double inside : {0.05, 0.1, p.closing_distance, 0.4}) {
    VelocityLaw law{p};
    TargetPolar t = target(d - inside, 0.0);
    t.receding_speed = 1.0;
    const double cap = std::max(0.0, 1.0 - inside / p.closing_distance);
    EXPECT_LE(law.update(t, 0.05).linear, cap + 1e-12) << inside;
  }
  VelocityLaw standing{p};
  EXPECT_EQ(standing.update(target(d - 0.05, 0.0), 0.05).linear, 0.0);
}

TEST(BrakingSpeed, StopsWithinTheRoomAfterTheReactionTime) {
  const double decel = 2.0;
  const double delay = 0.05;
  for (const double room : {0.05, 0.25, 1.0, 4.0}) {
    const double v = brakingSpeed(room, decel, delay);
    EXPECT_NEAR(v * delay + v * v / (2.0 * decel), room, 1e-12) << room;
  }
  EXPECT_EQ(brakingSpeed(0.0, decel, delay), 0.0);
  EXPECT_EQ(brakingSpeed(-0.3, decel, delay), 0.0);
  EXPECT_EQ(brakingSpeed(std::numeric_limits<double>::quiet_NaN(), decel, delay), 0.0);
}

// The person has stopped dead, but the estimate of their speed still says 1 m/s (a
// filter lags): braking at the base's deceleration from whatever the law commands, the
// robot comes to rest before the point where the law wants it at rest
// (follow_distance - closing_distance), never past it. Without the braking cap it ends
// 0.15 m past it.
TEST(VelocityLaw, BrakesInTimeForAPersonWhoStopsDead) {
  VelocityLawParams params;
  params.max_linear = 1.5;
  params.max_linear_decel = 2.0;
  VelocityLaw law(params);
  const double dt = 0.05;
  double range = 2.0;
  double speed = 1.5;
  for (int k = 0; k < 200; ++k) {
    TargetPolar t = target(range, 0.0);
    t.receding_speed = 1.0;
    const double commanded = law.update(t, dt).linear;
    // The base follows the command within its deceleration limit (and never faster).
    speed = std::max(std::min(commanded, speed), speed - params.max_linear_decel * dt);
    range -= speed * dt;
  }
  EXPECT_GE(range, params.follow_distance - params.closing_distance - 1e-9);
  EXPECT_LT(range, params.follow_distance);  // and it did close in
}

TEST(GoverningGap, TheNearestModuleGovernsWhenItIsCloserToTheStop) {
  VelocityLawParams p;  // stop_margin 0.1
  EXPECT_EQ(governingGap(0.4, std::numeric_limits<double>::infinity(), p), 0.4);
  EXPECT_EQ(governingGap(0.4, 1.0, p), 0.4);
  EXPECT_NEAR(governingGap(0.4, 0.25, p), 0.15, 1e-12);
  EXPECT_NEAR(governingGap(0.0, 0.05, p), -0.05, 1e-12);
  EXPECT_EQ(governingGap(0.4, std::nan(""), p), 0.4);
}

TEST(VelocityLaw, HangsBackWhenACornerModuleNearsTheStop) {
  // The centre is at the follow distance with the person walking away, but a corner
  // module is only 0.15 m beyond safe_distance: the regulated gap is the corner's, 0.05 m
  // (module gap - stop_margin), not the centre's 0.3 m: the person's speed plus kp x 0.05.
  // (A base that brakes at once: the braking cap is not what this test is about.)
  VelocityLawParams p;
  p.max_linear_decel = 1000.0;
  TargetPolar t = target(p.follow_distance + 0.3, 0.0);
  t.receding_speed = 0.5;
  VelocityLaw free_law{p};
  const double free_speed = free_law.update(t, 0.05).linear;
  t.module_gap = 0.15;
  VelocityLaw law{p};
  const double speed = law.update(t, 0.05).linear;
  EXPECT_NEAR(free_speed, 0.5 + p.linear.kp * 0.3, 1e-9);
  EXPECT_NEAR(speed, 0.5 + p.linear.kp * 0.05, 1e-9);
}

TEST(VelocityLaw, NeverDrivesIntoTheStopMarginWhateverTheEstimateSays) {
  // The estimate ran long (2 m) and says the person walks away at 1 m/s, while the raw
  // range puts them 0.05 m beyond safe_distance, inside stop_margin (0.1): before this
  // rule the closing zone's feed-forward drove the robot on (a simulated one-module robot
  // came to 1.21 m of a standing person this way).
  const VelocityLawParams p;
  TargetPolar t = target(2.0, 0.0);
  t.receding_speed = 1.0;
  for (const double module_gap : {0.05, p.stop_margin, -0.2}) {
    t.module_gap = module_gap;
    VelocityLaw law{p};
    EXPECT_EQ(law.update(t, 0.05).linear, 0.0) << "module gap " << module_gap;
  }
  t.module_gap = p.stop_margin + 0.05;
  VelocityLaw law{p};
  EXPECT_GT(law.update(t, 0.05).linear, 0.0);
  EXPECT_FALSE(insideStopMargin(std::numeric_limits<double>::infinity(), p));
  EXPECT_FALSE(insideStopMargin(std::nan(""), p));
}

TEST(VelocityLaw, AnArrivedRobotDoesNotInchTowardsAPersonWhoStands) {
  // At rest inside the follow distance, the estimate's noise moves it a few centimetres
  // out and gives it a small receding speed: the robot stays until the gap opens by more
  // than kArrivalHysteresis or the person walks away.
  const VelocityLawParams p;
  VelocityLaw law{p};
  TargetPolar t = target(p.follow_distance - 0.05, 0.0);
  law.update(t, 0.05);
  ASSERT_TRUE(law.arrived());
  t.range = p.follow_distance + 0.05;
  t.receding_speed = 0.15;
  EXPECT_EQ(law.update(t, 0.05).linear, 0.0);
  t.range = p.follow_distance + kArrivalHysteresis + 0.05;
  EXPECT_GT(law.update(t, 0.05).linear, 0.0);
  VelocityLaw walking{p};
  t.range = p.follow_distance - 0.05;
  walking.update(t, 0.05);
  t.receding_speed = kWalkingAwaySpeed + 0.1;  // the person walks off: follow at once
  EXPECT_GT(walking.update(t, 0.05).linear, 0.0);
}

TEST(VelocityLaw, NotArrivedWhileThePersonWalksAway) {
  VelocityLaw law{VelocityLawParams()};
  const double d = VelocityLawParams().follow_distance;
  TargetPolar t = target(d - 0.01, 0.0);
  t.receding_speed = 1.0;
  law.update(t, 0.05);
  EXPECT_FALSE(law.arrived());
  t.receding_speed = 0.0;
  law.update(t, 0.05);
  EXPECT_TRUE(law.arrived());
}

TEST(VelocityLaw, ArrivalHasHysteresis) {
  VelocityLaw law{VelocityLawParams()};
  const double d = VelocityLawParams().follow_distance;
  law.update(target(d + 0.5, 0.0), 0.05);
  EXPECT_FALSE(law.arrived());
  law.update(target(d - 0.01, 0.0), 0.05);
  EXPECT_TRUE(law.arrived());
  law.update(target(d + 0.05, 0.0), 0.05);  // noise: still arrived
  EXPECT_TRUE(law.arrived());
  law.update(target(d + kArrivalHysteresis + 0.01, 0.0), 0.05);
  EXPECT_FALSE(law.arrived());
  law.update(target(d + 0.05, 0.0), 0.05);  // approaching again: not yet arrived
  EXPECT_FALSE(law.arrived());
}

TEST(VelocityLaw, TurnsTowardsTargetOnTheLeft) {
  VelocityLaw law{VelocityLawParams()};
  const VelocityCommand cmd = law.update(target(3.0, 1.0), 0.05);
  EXPECT_GT(cmd.angular, 0.0);
  EXPECT_LT(cmd.linear, law.update(target(3.0, 0.0), 0.05).linear + 1.0);
}

TEST(VelocityLaw, NoForwardMotionWithTargetBeside) {
  VelocityLaw law{VelocityLawParams()};
  EXPECT_NEAR(law.update(target(3.0, kPi / 2.0), 0.05).linear, 0.0, 1e-12);
}

TEST(VelocityLaw, HeadingOnlyTurnsButDoesNotDrive) {
  VelocityLaw law{VelocityLawParams()};
  TargetPolar t = target(5.0, -0.5);
  t.range_valid = false;
  const VelocityCommand cmd = law.update(t, 0.05);
  EXPECT_EQ(cmd.linear, 0.0);
  EXPECT_LT(cmd.angular, 0.0);
}

// A DEGRADED estimate of a range-only robot far away: the range sure to 5 cm, the
// bearing to 7 deg (tracked.yaml at 6 m: 0.7 m sideways, so not OK there), which at the
// follow distance is 0.2 m sideways, within max_follow_sigma (0.5 m).
TargetPolar farRangeOnly() {
  TargetPolar t = target(6.0, 0.05);
  t.degraded = true;
  t.range_sigma = 0.05;
  t.bearing_sigma = deg2rad(7.0);
  return t;
}

TEST(VelocityLaw, ADegradedEstimateSureEnoughToSteerByIsFollowedAtFullSpeed) {
  VelocityLaw ok_law{VelocityLawParams()};
  VelocityLaw degraded_law{VelocityLawParams()};
  TargetPolar ok = farRangeOnly();
  ok.degraded = false;
  EXPECT_EQ(caution(farRangeOnly(), VelocityLawParams()), Caution::kNone);
  const double full = ok_law.update(ok, 0.05).linear;
  EXPECT_GT(full, 1.0);
  EXPECT_NEAR(degraded_law.update(farRangeOnly(), 0.05).linear, full, 1e-12);
  VelocityLaw law{VelocityLawParams()};
  EXPECT_EQ(law.step(farRangeOnly(), 0.05).text, "Following, the direction is approximate.");
  EXPECT_EQ(law.step(ok, 0.05).text, "Following.");
}

TEST(VelocityLaw, DegradedDrivesSlowerForAMirrorAWideBearingOrAWideRange) {
  const VelocityLawParams params;
  const double full = VelocityLaw(params).update(farRangeOnly(), 0.05).linear;
  TargetPolar mirror = farRangeOnly();
  mirror.mirror = true;
  TargetPolar wide_bearing = farRangeOnly();
  // 1.6 m x tan(18 deg) = 0.52 m sideways at the follow distance: beyond 0.5 m.
  wide_bearing.bearing_sigma = deg2rad(18.0);
  TargetPolar wide_range = farRangeOnly();
  wide_range.range_sigma = 0.6;
  TargetPolar unknown = farRangeOnly();
  unknown.bearing_sigma = std::numeric_limits<double>::infinity();
  const struct {
    TargetPolar target;
    Caution why;
    const char* text;
  } cases[] = {
      {mirror, Caution::kMirror, "Following slowly, the target may be at its mirror image."},
      {wide_bearing, Caution::kBearing, "Following slowly, the direction is uncertain."},
      {wide_range, Caution::kRange, "Following slowly, the distance is uncertain."},
      {unknown, Caution::kBearing, "Following slowly, the direction is uncertain."},
  };
  for (const auto& c : cases) {
    EXPECT_EQ(caution(c.target, params), c.why) << c.text;
    VelocityLaw law(params);
    const LawOutput out = law.step(c.target, 0.05);
    EXPECT_NEAR(out.command.linear, params.degraded_speed_factor * full, 1e-12) << c.text;
    EXPECT_EQ(out.text, c.text);
  }
  // The same spreads on an OK estimate: the locator vouches for it, full speed.
  mirror.degraded = false;
  wide_bearing.degraded = false;
  EXPECT_EQ(caution(mirror, params), Caution::kNone);
  EXPECT_EQ(caution(wide_bearing, params), Caution::kNone);
}

TEST(VelocityLaw, MaxFollowSigmaIsLiveTunable) {
  VelocityLawParams params;
  params.max_follow_sigma = 0.1;  // 1.6 m x tan(7 deg) = 0.196 m: too wide now
  EXPECT_EQ(caution(farRangeOnly(), params), Caution::kBearing);
  params.max_follow_sigma = 0.0;
  EXPECT_THROW(params.validate(), ParamError);
}

TEST(VelocityLaw, SwitchesToBackwardsAfterFiveCyclesBehind) {
  VelocityLawParams params;
  params.allow_backwards = true;
  VelocityLaw law(params);
  const TargetPolar behind = target(3.0, deg2rad(170.0));
  for (int i = 0; i < 4; ++i) {
    law.update(behind, 0.05);
    EXPECT_FALSE(law.driving_backwards()) << i;
  }
  const VelocityCommand cmd = law.update(behind, 0.05);
  EXPECT_TRUE(law.driving_backwards());
  EXPECT_LT(cmd.linear, 0.0);
}

TEST(VelocityLaw, ShortGlimpseBehindDoesNotSwitch) {
  VelocityLawParams params;
  params.allow_backwards = true;
  VelocityLaw law(params);
  for (int i = 0; i < 20; ++i) {
    law.update(target(3.0, i % 4 == 3 ? 0.0 : deg2rad(170.0)), 0.05);
  }
  EXPECT_FALSE(law.driving_backwards());
}

TEST(VelocityLaw, WithoutBackwardsOptionItTurnsAround) {
  VelocityLaw law{VelocityLawParams()};
  VelocityCommand cmd;
  for (int i = 0; i < 10; ++i) {
    cmd = law.update(target(3.0, deg2rad(170.0)), 0.05);
  }
  EXPECT_FALSE(law.driving_backwards());
  EXPECT_EQ(cmd.linear, 0.0);
  EXPECT_GT(cmd.angular, 0.0);
}

TEST(VelocityLawParams, ValidateRejectsBadFollowDistance) {
  VelocityLawParams params;
  params.follow_distance = 0.0;
  EXPECT_THROW(params.validate(), ParamError);
  EXPECT_NO_THROW(VelocityLawParams().validate());
}

TEST(VelocityLawParams, ValidateRejectsAClosingDistanceOutsideTheFollowDistance) {
  for (const double closing : {0.0, -0.1, 1.6, 2.0, std::nan("")}) {
    VelocityLawParams params;
    params.closing_distance = closing;
    try {
      params.validate();
      ADD_FAILURE() << closing << " accepted";
    } catch (const ParamError& e) {
      EXPECT_EQ(e.name(), "~closing_distance");
    }
  }
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
