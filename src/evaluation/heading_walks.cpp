// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/heading_walks.hpp"

#include <cmath>
#include <optional>
#include <random>
#include <utility>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/evaluation/standing_robot.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

/// The person's path: positions at key times, straight lines between them.
struct Keyframe {
  double t;
  Eigen::Vector2d p;
};

/// A walk of `duration` from waypoint to waypoint in the board's front sector, with
/// pauses; `board` and `yaw` place the sector.
std::vector<Keyframe> drawWalk(const HeadingWalkParams& params, const Eigen::Vector2d& board,
                               double yaw, sim::Rng& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto waypoint = [&] {
    const double d = params.min_distance + (params.max_distance - params.min_distance) * unit(rng);
    const double a = yaw + params.max_direction * (2.0 * unit(rng) - 1.0);
    return Eigen::Vector2d(board + d * Eigen::Vector2d(std::cos(a), std::sin(a)));
  };
  std::vector<Keyframe> keys{{0.0, waypoint()}};
  while (keys.back().t < params.duration) {
    const Keyframe& last = keys.back();
    if (unit(rng) < params.stand_probability) {
      const double stand = params.min_stand + (params.max_stand - params.min_stand) * unit(rng);
      keys.push_back({last.t + stand, last.p});
    }
    const Eigen::Vector2d next = waypoint();
    keys.push_back({keys.back().t + (next - keys.back().p).norm() / params.speed, next});
  }
  return keys;
}

Eigen::Vector2d at(const std::vector<Keyframe>& keys, double t) {
  for (std::size_t i = 1; i < keys.size(); ++i) {
    if (t <= keys[i].t) {
      const double span = keys[i].t - keys[i - 1].t;
      const double s = span > 0.0 ? (t - keys[i - 1].t) / span : 1.0;
      return keys[i - 1].p + s * (keys[i].p - keys[i - 1].p);
    }
  }
  return keys.back().p;
}

double yawOf(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d r = q.toRotationMatrix();
  return std::atan2(r(1, 0), r(0, 0));
}

}  // namespace

void HeadingWalkParams::validate() const {
  require(walks >= 1, "walks", walks, "a count >= 1");
  require(std::isfinite(duration) && duration > settle, "duration", duration, "seconds > settle");
  require(std::isfinite(settle) && settle >= 0.0, "settle", settle, "seconds >= 0");
  require(min_distance > 0.0 && max_distance >= min_distance, "max_distance", max_distance,
          "metres >= min_distance > 0");
  require(max_direction > 0.0 && max_direction < 0.5 * kPi, "max_direction", max_direction,
          "an angle in (0, pi/2): the person stays in front");
  require(speed > 0.0, "speed", speed, "m/s > 0");
  require(stand_probability >= 0.0 && stand_probability <= 1.0, "stand_probability",
          stand_probability, "a probability");
  require(min_stand >= 0.0 && max_stand >= min_stand, "max_stand", max_stand,
          "seconds >= min_stand >= 0");
  require(robots >= 1, "robots", robots, "a count >= 1");
}

HeadingWalkResult runHeadingWalks(const Layout& layout, sim::WorldConfig world,
                                  const estimation::LocatorConfig& locator,
                                  const HeadingWalkParams& params) {
  params.validate();
  require(!layout.aoa_boards.empty(), "layout", layout.aoa_boards.size(), "at least one AoA board");
  Layout one_board = layout;
  one_board.twr_modules.clear();
  one_board.tdoa_anchors.clear();
  one_board.aoa_boards.resize(1);
  const AoaBoard& board = one_board.aoa_boards.front();
  const double board_yaw = yawOf(board.orientation);

  HeadingWalkResult result;
  sim::Rng rng(params.seed);
  for (int k = 0; k < params.walks; ++k) {
    world.hardware_seed = 1 + static_cast<std::uint64_t>(k % params.robots);
    const std::vector<Keyframe> walk = drawWalk(params, board.position.head<2>(), board_yaw, rng);
    estimation::Locator estimator(one_board, locator);
    StandingRobotSensors sensors(one_board, world, world.hardware_seed, rng);
    // The newest reading: its heading in the robot frame and its time.
    std::optional<std::pair<double, double>> raw;
    sensors.observeReadings([&](const SensorReading& r) {
      if (r.kind == SensorReading::Kind::kBearing) {
        raw = std::make_pair(wrapAngle(board_yaw + r.value), r.t);
      }
    });
    const auto target = [&](double t) {
      const Eigen::Vector2d p = at(walk, t);
      return Eigen::Vector3d(p.x(), p.y(), locator.height);
    };
    double last_error = std::nan("");
    for (double now = kLocatorUpdatePeriod; now <= params.duration + 1e-9; now += kLocatorUpdatePeriod) {
      sensors.feed(estimator, now, target, rng);
      const estimation::LocatorEstimate e = estimator.update(now);
      if (now < params.settle) {
        continue;
      }
      ++result.updates;
      const bool directed = hasPosition(e.status) || e.status == TargetStatus::kHeadingOnly;
      if (!directed || !raw) {
        result.without_direction += !directed;
        continue;
      }
      // Headings from the board, where the raw reading is taken, each against where the
      // person was at its own time (the estimate's stamp is its newest reading's).
      const auto direction = [&](double t) {
        const Eigen::Vector2d d = at(walk, t) - board.position.head<2>();
        return std::atan2(d.y(), d.x());
      };
      const Eigen::Vector2d estimate = e.position.head<2>() - board.position.head<2>();
      last_error =
          std::abs(wrapAngle(std::atan2(estimate.y(), estimate.x()) - direction(e.stamp)));
      result.locator_deg.push_back(rad2deg(last_error));
      result.raw_deg.push_back(rad2deg(std::abs(wrapAngle(raw->first - direction(raw->second)))));
    }
    ++result.walks;
    result.ended_behind += last_error > 0.5 * kPi;
  }
  return result;
}

}  // namespace evaluation
}  // namespace radio_follow
