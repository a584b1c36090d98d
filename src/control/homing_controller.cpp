// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/homing_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/plausibility.hpp"

namespace radio_follow {
namespace control {

namespace {

const ParamTable<RssiModel>& rssiTable() {
  static const ParamTable<RssiModel> t =
      ParamTable<RssiModel>()
          .add("rssi_at_1m", &RssiModel::rssi_at_1m, "dBm", "RSSI of the tag at 1 m.")
          .add("rssi_exponent", &RssiModel::exponent, "", "Path-loss exponent.", Range::above(0.0));
  return t;
}

const ParamTable<HomingParams>& estimatorTable() {
  using H = HomingParams;
  static const ParamTable<H> t =
      ParamTable<H>()
          .addChoice("goal_estimator", &H::goal_estimator,
                     std::vector<std::pair<std::string, std::string>>{
                         {"all_readings", "all_readings"}, {"seed000", "seed000"}},
                     "all_readings: fit of every reading; seed000: the hybrid rule's goal.")
          .add("tau", &H::tau, "readings", "Eq 3 decay.", Range::above(0.0))
          .add("window", &H::window, "", "Vector goals kept.", Range::atLeast(3))
          .add("kohonen_k", &H::k, "", "Kohonen step.", Range::aboveUpTo(0.0, 1.0))
          .add("min_baseline", &H::min_baseline, "m", "Parallax baseline needed.",
               Range::above(0.0))
          .add("min_parallax_angle", &H::min_parallax_angle, "rad", "Parallax angle needed.",
               Range::open(0.0, kPi / 2.0))
          .add("error_threshold", &H::error_threshold, "", "Eq 14 threshold.", Range::above(0.0))
          .add("range_step", &H::range_step, "",
               "Step of the parallax goal towards the vector goal's distance (0 = seed 000's law).",
               Range::closed(0.0, 1.0))
          .add("z_threshold", &H::z_threshold, "", "One-sided z of the agreement test.",
               Range::above(0.0))
          .add("arrival_distance", &H::arrival_distance, "m", "Arrived within this.",
               Range::above(0.0))
          .add("agreement_distance", &H::agreement_distance, "m",
               "Parallax vs vector goal at arrival.", Range::above(0.0))
          .add("linear_gain", &H::linear_gain, "1/s", "speed = min(max_linear, gain * distance).",
               Range::above(0.0))
          .add("angular_gain", &H::angular_gain, "1/s", "Yaw rate per rad of heading error.",
               Range::above(0.0));
  return t;
}

}  // namespace

const ParamTable<HomingControllerParams>& HomingControllerParams::table() {
  using P = HomingControllerParams;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("board_x", &P::board_x, "m", "AoA board position in base_link, x.")
          .add("board_y", &P::board_y, "m", "AoA board position in base_link, y.")
          .add("board_yaw", &P::board_yaw, "rad", "Yaw of the board's boresight.")
          .addChoice(
              "distance_source", &P::distance_source,
              std::vector<std::pair<std::string, std::string>>{{"rssi", "rssi"}, {"uwb", "uwb"}},
              "rssi: log-distance model; uwb: the newest range.")
          .add("distance_max_age", &P::distance_max_age, "s", "Older UWB ranges are not used.",
               Range::above(0.0))
          .add("odom_timeout", &P::odom_timeout, "s", "Older odometry is not used.",
               Range::above(0.0))
          .add("search_speed", &P::search_speed, "m/s", "Forward speed while no goal exists.",
               Range::atLeast(0.0))
          .add("target_height", &P::target_height, "m",
               "Height of the target's UWB antenna in base_link (slant range to horizontal).")
          .include(rssiTable(), &P::rssi)
          .include(RssiFilterParams::table(), &P::rssi_filter, "rssi_filter/")
          .include(estimatorTable(), &P::homing);
  return t;
}

void HomingControllerParams::validate() const {
  table().check(*this);
  rssi_filter.validate();
  homing.validate();  // max_linear and max_angular, copied from the common limits
}

HomingController::HomingController(const HomingControllerParams& params)
    : params_([&] {
        params.validate();
        return params;
      }()),
      homing_(params_.homing),
      rssi_filter_(params_.rssi_filter) {}

void HomingController::reset() {
  robot_.reset();
  last_bearing_.reset();
  range_stamp_.reset();
  range_antenna_.reset();
  rssi_filter_.reset();
  homing_ = HybridHoming(params_.homing);
}

HomingController::OdometryResult HomingController::onOdometry(const Pose2& pose, double stamp,
                                                              double now) {
  OdometryResult result;
  if (time_.jumpedBack(now)) {
    reset();
    result.clock_jumped = true;
  }
  if (!plausibleOdometryCoordinate(pose.x) || !plausibleOdometryCoordinate(pose.y) ||
      !std::isfinite(pose.yaw) ||
      time_.check(stamp, now) == TimePolicy::Verdict::kFuture) {
    ++odom_refused_;
    return result;
  }
  robot_ = pose;
  odom_stamp_ = stamp;
  result.accepted = true;
  return result;
}

void HomingController::onRange(double range, double stamp,
                               const std::optional<Eigen::Vector3d>& antenna) {
  // The drivers' bounds (plausibility.hpp): an implausible range is no distance at all.
  if (plausibleRange(range) && (!antenna || antenna->allFinite())) {
    range_ = range;
    range_stamp_ = stamp;
    range_antenna_ = antenna;
  }
}

double HomingController::distanceAt(double stamp, std::optional<double> filtered) const {
  if (!params_.usesUwb()) {
    return filtered ? params_.rssi.distance(*filtered) : std::numeric_limits<double>::quiet_NaN();
  }
  if (range_stamp_ && std::abs(stamp - *range_stamp_) <= params_.distance_max_age) {
    return range_;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

HomingController::BearingResult HomingController::onBearing(double azimuth, double rssi,
                                                            double stamp) {
  // The RSSI reading stands on its own: it is smoothed even when the bearing cannot be
  // placed, so the filter's history has no holes where odometry lagged. A NaN (no RSSI)
  // is refused by the filter and leaves this bearing without a distance.
  const std::optional<double> filtered =
      params_.usesUwb() ? std::nullopt : rssi_filter_.update(rssi);
  if (!robot_ || std::abs(stamp - odom_stamp_) > params_.odom_timeout) {
    return BearingResult::kNoOdometry;
  }
  if (!plausibleAngleRad(azimuth)) {
    return BearingResult::kNotFinite;
  }
  // The board's position and boresight in the odometry frame.
  const Eigen::Vector2d sensor =
      robot_->toFixed(Eigen::Vector3d(params_.board_x, params_.board_y, 0.0)).head<2>();
  const double bearing = wrapAngle(robot_->yaw + params_.board_yaw + azimuth);
  double distance = distanceAt(stamp, filtered);
  if (params_.usesUwb() && range_antenna_ && std::isfinite(distance)) {
    distance = distanceAlongBearing(sensor, bearing, robot_->toFixed(*range_antenna_).head<2>(),
                                    params_.target_height - range_antenna_->z(), distance);
  }
  homing_.update(sensor, bearing, distance);
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

void HomingControllerParams::load(const ParamSource& source, const MotionLimits& limits) {
  table().load(source, *this);
  homing.max_linear = limits.max_linear;
  homing.max_angular = limits.max_angular;
}

}  // namespace control
}  // namespace radio_follow
