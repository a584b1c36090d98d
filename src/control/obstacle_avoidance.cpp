// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/obstacle_avoidance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {

const ParamTable<AvoidanceParams>& AvoidanceParams::table() {
  static const ParamTable<AvoidanceParams> t =
      ParamTable<AvoidanceParams>()
          .add("avoidance/obstacle_threshold", &AvoidanceParams::obstacle_threshold, "m",
               "Slow and bend below this (ahead).", Range::above(0.0))
          .add("avoidance/stop_threshold", &AvoidanceParams::stop_threshold, "m",
               "No forward motion below this (ahead).", Range::above(0.0))
          .add("avoidance/side_threshold", &AvoidanceParams::side_threshold, "m",
               "Turn away from a side below this; the swept strip's half-width.", Range::above(0.0))
          .add("avoidance/turn_rate", &AvoidanceParams::turn_rate, "rad/s",
               "Yaw rate used to bend.", Range::above(0.0));
  return t;
}

void AvoidanceParams::validate() const {
  table().check(*this);
  require(obstacle_threshold > stop_threshold, "~avoidance/obstacle_threshold", obstacle_threshold,
          "a distance in metres above stop_threshold");
}

SectorRanges scanSectors(const std::vector<float>& ranges, double angle_min, double angle_increment,
                         double range_min, double range_max, double corridor_half_width) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  SectorRanges s{kInf, kInf, kInf, kInf, kInf};
  const double side = deg2rad(30.0);
  const double narrow = deg2rad(18.0);  // 20 % of the 180 deg field
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const double r = ranges[i];
    if (!std::isfinite(r) || r < range_min || r > range_max) {
      continue;
    }
    const double a = wrapAngle(angle_min + angle_increment * static_cast<double>(i));
    if (a > kPi / 2.0 || a < -kPi / 2.0) {
      continue;
    }
    if (std::abs(r * std::sin(a)) < corridor_half_width) {
      s.corridor = std::min(s.corridor, r * std::cos(a));
    }
    if (a > side) {
      s.left = std::min(s.left, r);
    } else if (a < -side) {
      s.right = std::min(s.right, r);
    } else {
      s.centre = std::min(s.centre, r);
      if (std::abs(a) <= narrow) {
        s.centre_narrow = std::min(s.centre_narrow, r);
      }
    }
  }
  return s;
}

VelocityCommand avoidObstacles(const VelocityCommand& command, const SectorRanges& sectors,
                               const AvoidanceParams& params) {
  VelocityCommand out = command;
  const double front = std::min({sectors.centre, sectors.centre_narrow, sectors.corridor});
  const double freer_side = sectors.left >= sectors.right ? 1.0 : -1.0;
  if (command.linear > 0.0 && front < params.stop_threshold) {
    out.linear = 0.0;
    out.angular = freer_side * params.turn_rate;
  } else if (command.linear > 0.0 && front < params.obstacle_threshold) {
    const double scale =
        (front - params.stop_threshold) / (params.obstacle_threshold - params.stop_threshold);
    out.linear = command.linear * std::clamp(scale, 0.0, 1.0);
    out.angular = freer_side * params.turn_rate;
  }
  if (sectors.left < params.side_threshold && sectors.right >= params.side_threshold) {
    out.angular = std::min(out.angular, -params.turn_rate);
  } else if (sectors.right < params.side_threshold && sectors.left >= params.side_threshold) {
    out.angular = std::max(out.angular, params.turn_rate);
  }
  return out;
}

}  // namespace control
}  // namespace radio_follow
