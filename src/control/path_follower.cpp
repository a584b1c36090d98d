// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/path_follower.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {

PathBuffer::PathBuffer(double min_spacing, std::size_t max_points)
    : min_spacing_(min_spacing), max_points_(max_points) {}

bool PathBuffer::add(const Eigen::Vector2d& point) {
  if (!point.allFinite()) {
    return false;
  }
  if (!points_.empty() && (point - points_.back()).norm() < min_spacing_) {
    return false;
  }
  points_.push_back(point);
  while (points_.size() > max_points_) {
    points_.pop_front();
  }
  return true;
}

void PathBuffer::prune(const Eigen::Vector2d& robot, double reached_radius) {
  if (points_.empty()) {
    return;
  }
  std::size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const double d = (points_[i] - robot).norm();
    if (d < best) {
      best = d;
      nearest = i;
    }
  }
  std::size_t drop = nearest;
  // Keep the newest point: it is where the person is, the robot must never lose it.
  if (best < reached_radius && nearest + 1 < points_.size()) {
    drop = nearest + 1;
  }
  points_.erase(points_.begin(), points_.begin() + static_cast<std::ptrdiff_t>(drop));
}

double PathBuffer::lengthFrom(const Eigen::Vector2d& robot) const {
  if (points_.empty()) {
    return 0.0;
  }
  double length = (points_.front() - robot).norm();
  for (std::size_t i = 1; i < points_.size(); ++i) {
    length += (points_[i] - points_[i - 1]).norm();
  }
  return length;
}

PursuitTarget purePursuit(const std::deque<Eigen::Vector2d>& path, const Pose2& robot,
                          double lookahead) {
  PursuitTarget target;
  if (path.empty()) {
    return target;
  }
  target.point = path.back();
  for (const auto& p : path) {
    if ((p - robot.position()).norm() >= lookahead) {
      target.point = p;
      break;
    }
  }
  const Eigen::Vector2d delta = target.point - robot.position();
  const double c = std::cos(robot.yaw);
  const double s = std::sin(robot.yaw);
  target.local = Eigen::Vector2d(c * delta.x() + s * delta.y(), -s * delta.x() + c * delta.y());
  const double l2 = target.local.squaredNorm();
  target.curvature = l2 > 1e-12 ? 2.0 * target.local.y() / l2 : 0.0;
  target.valid = true;
  return target;
}

const ParamTable<PathFollowParams>& PathFollowParams::table() {
  using P = PathFollowParams;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("path_spacing", &P::path_spacing, "m", "Minimum spacing of stored path points.",
               Range::above(0.0))
          .add("max_path_points", &P::max_path_points, "", "Path buffer size.", Range::atLeast(2))
          .add("lookahead", &P::lookahead, "m", "Pure-pursuit lookahead distance.",
               Range::above(0.0))
          .add("reached_radius", &P::reached_radius, "m",
               "A path point this close to the robot is dropped.", Range::above(0.0))
          .add("turn_gain", &P::turn_gain, "1/s",
               "Yaw rate per rad when turning in place towards a goal behind.", Range::above(0.0));
  return t;
}

void PathFollowParams::load(const ParamSource& p) {
  table().load(p, *this);
}

void PathFollowParams::validate() const {
  table().check(*this);
}

PathFollowLaw::PathFollowLaw(const PathFollowParams& params, const VelocityLawParams& law)
    : params_(params),
      law_(law),
      fallback_(law),
      speed_pid_(law.linear),
      path_(params.path_spacing, static_cast<std::size_t>(params.max_path_points)) {}

void PathFollowLaw::setLawParams(const VelocityLawParams& law) {
  law_ = law;
  fallback_.setParams(law);
  speed_pid_.setGains(law.linear);
}

void PathFollowLaw::setCommon(const CommandPipelineParams& next) {
  setLawParams(lawWithCommon(law_, next));
}

LawOutput PathFollowLaw::step(const FollowInput& input, double dt) {
  if (!input.target) {
    LawOutput out;
    out.state = FollowerState::kWaitingForTarget;
    return out;
  }
  return step(*input.target, input.robot, input.walking_speed, dt);
}

void PathFollowLaw::reset() {
  fallback_.reset();
  speed_pid_.reset();
  arrived_ = false;
}

LawOutput PathFollowLaw::step(const TargetPolar& target, const std::optional<Pose2>& robot,
                              std::optional<double> walking_speed, double dt) {
  if (!robot || path_.empty() || !target.range_valid) {
    // Without self-localisation no path can be stored, and before the first track point
    // (TrackGate) there is none yet: drive straight at the target.
    TargetPolar straight = target;
    straight.receding_speed = 0.0;
    LawOutput out = fallback_.step(straight, dt);
    if (target.range_valid && !fallback_.arrived()) {
      out.text = !robot ? "No odometry, driving straight to the target."
                        : "No path yet, driving straight to the target.";
    }
    return out;
  }

  LawOutput out;
  path_.prune(robot->position(), params_.reached_radius);
  const PursuitTarget goal = purePursuit(path_.points(), *robot, params_.lookahead);
  // A path built from noisy estimates zig-zags and is longer than the walk; the straight
  // range is never longer than the walk. The smaller of the two keeps the robot from
  // closing in on a person who has stopped because their path looked long.
  const double along = path_.lengthFrom(robot->position());
  const double gap =
      governingGap(std::min(along, target.range) - law_.follow_distance, target.module_gap, law_);
  const double alpha = std::atan2(goal.local.y(), goal.local.x());
  // The person walks the path ahead: the feed-forward is their whole ground speed.
  const double speed_ahead = walking_speed.value_or(0.0);
  double speed = gapSpeed(gap, speed_ahead, dt, speed_pid_, law_);
  arrived_ = updateArrived(arrived_, gap, speed_ahead);
  if (arrived_ || insideStopMargin(target.module_gap, law_)) {
    speed = 0.0;
  }
  speed *= std::max(0.0, std::cos(alpha));
  const Caution why = caution(target, law_);
  if (why != Caution::kNone) {
    speed *= law_.degraded_speed_factor;
  }
  out.command.linear = speed;
  // Pure pursuit steers along the arc; a goal behind the robot (after it stopped and the
  // person walked around it) needs turning in place first.
  out.command.angular =
      std::abs(alpha) > 0.5 * M_PI ? params_.turn_gain * alpha : speed * goal.curvature;
  if (arrived_) {
    out.state = FollowerState::kArrived;
    out.text = "At follow distance, waiting.";
  } else {
    out.text = followingText("Following the path", target, why);
  }
  return out;
}

}  // namespace control
}  // namespace radio_follow
