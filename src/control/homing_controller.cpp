// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/homing_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {

void HomingControllerParams::validate() const {
  require(std::isfinite(board_x) && std::isfinite(board_y), "~board_x/~board_y", board_x,
          "finite metres");
  require(std::isfinite(board_yaw), "~board_yaw", board_yaw, "a finite angle in rad");
  require(distance_source == "rssi" || distance_source == "uwb", "~distance_source",
          distance_source, "'rssi' or 'uwb'");
  require(distance_max_age > 0.0, "~distance_max_age", distance_max_age, "seconds > 0");
  require(odom_timeout > 0.0, "~odom_timeout", odom_timeout, "seconds > 0");
  require(search_speed >= 0.0, "~search_speed", search_speed, "a speed >= 0 in m/s");
  rssi.validate();
  homing.validate();
}

HomingController::HomingController(const HomingControllerParams& params)
    : params_([&] {
        params.validate();
        return params;
      }()),
      homing_(params_.homing) {}

void HomingController::reset() {
  robot_.reset();
  last_bearing_.reset();
  range_stamp_.reset();
  homing_ = HybridHoming(params_.homing);
}

HomingController::OdometryResult HomingController::onOdometry(const Pose2& pose, double stamp,
                                                              double now) {
  OdometryResult result;
  if (time_.jumpedBack(now)) {
    reset();
    result.clock_jumped = true;
  }
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.yaw) ||
      time_.check(stamp, now) == TimePolicy::Verdict::kFuture) {
    ++odom_refused_;
    return result;
  }
  robot_ = pose;
  odom_stamp_ = stamp;
  result.accepted = true;
  return result;
}

void HomingController::onRange(double range, double stamp) {
  if (std::isfinite(range) && range >= 0.0) {
    range_ = range;
    range_stamp_ = stamp;
  }
}

double HomingController::distanceAt(double stamp, double rssi) const {
  if (!params_.usesUwb()) {
    return std::isfinite(rssi) ? params_.rssi.distance(rssi)
                               : std::numeric_limits<double>::quiet_NaN();
  }
  if (range_stamp_ && std::abs(stamp - *range_stamp_) <= params_.distance_max_age) {
    return range_;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

HomingController::BearingResult HomingController::onBearing(double azimuth, double rssi,
                                                            double stamp) {
  if (!robot_ || std::abs(stamp - odom_stamp_) > params_.odom_timeout) {
    return BearingResult::kNoOdometry;
  }
  if (!std::isfinite(azimuth)) {
    return BearingResult::kNotFinite;
  }
  // The board's position and boresight in the odometry frame.
  const double c = std::cos(robot_->yaw);
  const double s = std::sin(robot_->yaw);
  const Eigen::Vector2d sensor(robot_->x + c * params_.board_x - s * params_.board_y,
                               robot_->y + s * params_.board_x + c * params_.board_y);
  const double bearing = wrapAngle(robot_->yaw + params_.board_yaw + azimuth);
  homing_.update(sensor, bearing, distanceAt(stamp, rssi));
  last_bearing_ = bearing;
  return BearingResult::kUsed;
}

std::optional<Pose2> HomingController::goalPose() const {
  if (!homing_.goal() || !robot_) {
    return std::nullopt;
  }
  const Eigen::Vector2d& goal = *homing_.goal();
  Pose2 pose;
  pose.x = goal.x();
  pose.y = goal.y();
  pose.yaw = std::atan2(goal.y() - robot_->y, goal.x() - robot_->x);
  return pose;
}

HomingOutput HomingController::compute(double now) const {
  HomingOutput out;
  if (!robot_ || now - odom_stamp_ > params_.odom_timeout) {
    out.state = FollowerState::kWaitingForTarget;
    out.text = "No odometry, waiting.";
    return out;
  }
  if (!homing_.goal()) {
    // No distance and no parallax yet: creep along the bearing so the parallax estimate
    // gets its baseline (seed 000 needs two readings taken at different places).
    out.state = FollowerState::kWaitingForTarget;
    out.text = "Searching for the target.";
    if (last_bearing_) {
      HomingParams search = params_.homing;
      search.max_linear = std::min(search.max_linear, params_.search_speed);
      const Eigen::Vector2d ahead =
          robot_->position() + Eigen::Vector2d(std::cos(*last_bearing_), std::sin(*last_bearing_));
      out.command = homingVelocity(*robot_, ahead, search);
    }
    return out;
  }
  if (homing_.arrived(robot_->position())) {
    out.state = FollowerState::kArrived;
    out.text = "Arrived at the target.";
    return out;
  }
  out.command = homingVelocity(*robot_, *homing_.goal(), params_.homing);
  out.text = "Homing to the target.";
  return out;
}

void HomingControllerParams::load(const ParamSource& pnh, const MotionLimits& limits) {
  HomingControllerParams& p = *this;
  pnh.param("board_x", p.board_x, p.board_x);
  pnh.param("board_y", p.board_y, p.board_y);
  pnh.param("board_yaw", p.board_yaw, p.board_yaw);
  pnh.param("distance_source", p.distance_source, p.distance_source);
  pnh.param("distance_max_age", p.distance_max_age, p.distance_max_age);
  pnh.param("odom_timeout", p.odom_timeout, p.odom_timeout);
  pnh.param("search_speed", p.search_speed, p.search_speed);
  pnh.param("rssi_at_1m", p.rssi.rssi_at_1m, p.rssi.rssi_at_1m);
  pnh.param("rssi_exponent", p.rssi.exponent, p.rssi.exponent);
  HomingParams& h = p.homing;
  pnh.param("tau", h.tau, h.tau);
  pnh.param("window", h.window, h.window);
  pnh.param("kohonen_k", h.k, h.k);
  pnh.param("min_baseline", h.min_baseline, h.min_baseline);
  pnh.param("min_parallax_angle", h.min_parallax_angle, h.min_parallax_angle);
  pnh.param("error_threshold", h.error_threshold, h.error_threshold);
  pnh.param("z_threshold", h.z_threshold, h.z_threshold);
  pnh.param("arrival_distance", h.arrival_distance, h.arrival_distance);
  pnh.param("agreement_distance", h.agreement_distance, h.agreement_distance);
  pnh.param("linear_gain", h.linear_gain, h.linear_gain);
  pnh.param("angular_gain", h.angular_gain, h.angular_gain);
  h.max_linear = limits.max_linear;
  h.max_angular = limits.max_angular;
}

}  // namespace control
}  // namespace radio_follow
