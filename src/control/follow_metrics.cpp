// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/follow_metrics.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/error_statistics.hpp"

namespace radio_follow {
namespace control {

const ParamTable<FollowEvaluatorParams>& FollowEvaluatorParams::table() {
  using P = FollowEvaluatorParams;
  using S = FollowSettings;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("report_dir", &P::report_dir, "", "Where to write; empty = log only.")
          .add("rate", &P::rate, "Hz", "Sampling rate.", Range::aboveUpTo(0.0, 1000.0))
          .add("write_period", &P::write_period, "s", "Report rewrite period.", Range::above(0.0))
          .add("end_launch", &P::end_launch, "", "End the roslaunch when the scenario ends.")
          .add("controller", &P::controller, "", "The controller node the run is judged by.")
          .add("follow_distance", &P::settings, &S::follow_distance, "m",
               "Gap the controller holds (only without controller).", Range::above(0.0))
          .add("safe_distance", &P::settings, &S::safe_distance, "m",
               "Nearest allowed gap while moving (only without controller).", Range::above(0.0))
          .add("gap_tolerance", &P::settings, &S::gap_tolerance, "m",
               "A gap within follow_distance +- this counts as held.", Range::above(0.0))
          .add("robot_max_speed", &P::settings, &S::robot_max_speed, "m/s",
               "Gap statistics only while the person walks slower than this.", Range::above(0.0))
          .add("settle_time", &P::settings, &S::settle_time, "s",
               "Gap and path statistics start after this.", Range::atLeast(0.0))
          .add("judge_following", &P::settings, &S::judge_following, "",
               "The verdict also judges how well the robot followed.")
          .add("min_gap_held", &P::settings, &S::min_gap_held, "",
               "The least share of the walk the gap must be held.", Range::closed(0.0, 1.0));
  return t;
}

void FollowEvaluatorParams::validate() const {
  table().check(*this);
}

namespace {

/// Path points closer than this are merged: the person's path at 5 cm resolution.
constexpr double kPathResolution = 0.05;

struct PathPoint {
  double x;
  double y;
  double s;            ///< arc length, m
  std::size_t sample;  ///< index of the sample that added it
  bool turn = false;
};

std::vector<PathPoint> buildPath(const std::vector<FollowSample>& samples,
                                 const FollowSettings& settings) {
  std::vector<PathPoint> path;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double x = samples[i].target_x;
    const double y = samples[i].target_y;
    if (path.empty()) {
      path.push_back(PathPoint{x, y, 0.0, i});
      continue;
    }
    const double step = std::hypot(x - path.back().x, y - path.back().y);
    if (step >= kPathResolution) {
      path.push_back(PathPoint{x, y, path.back().s + step, i});
    }
  }
  // Heading over a window of path on each side; a large change marks a turn.
  auto headingAt = [&path](std::size_t a, std::size_t b) {
    return std::atan2(path[b].y - path[a].y, path[b].x - path[a].x);
  };
  const double half = 0.5 * settings.turn_window;
  std::size_t lo = 0;
  std::size_t hi = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    while (lo < i && path[i].s - path[lo].s > half)
      ++lo;
    while (hi + 1 < path.size() && path[hi + 1].s - path[i].s <= half)
      ++hi;
    if (lo < i && hi > i) {
      const double change = std::abs(wrapAngleFast(headingAt(i, hi) - headingAt(lo, i)));
      path[i].turn = change > settings.turn_heading_change;
    }
  }
  // Widen each turn by half a window on both sides: a follower cuts a corner over
  // roughly its look-ahead distance, before and after the bend itself.
  std::vector<bool> widened(path.size(), false);
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (!path[i].turn) {
      continue;
    }
    for (std::size_t j = i; j > 0 && path[i].s - path[j - 1].s <= half; --j)
      widened[j - 1] = true;
    for (std::size_t j = i; j < path.size() && path[j].s - path[i].s <= half; ++j)
      widened[j] = true;
  }
  for (std::size_t i = 0; i < path.size(); ++i) {
    path[i].turn = widened[i];
  }
  return path;
}

}  // namespace

void FollowMetrics::add(const FollowSample& sample) {
  samples_.push_back(sample);
}

void FollowMetrics::addClearance(double t, double clearance) {
  min_clearance_ = std::min(min_clearance_, clearance);
  if (clearance < 0.0 && std::isnan(collision_time_)) {
    collision_time_ = t;
  }
}

namespace {
/// Below this the person counts as standing (the gap is only judged while they walk), m/s.
constexpr double kStandingSpeed = 0.05;
}  // namespace

void FollowMetrics::judgeFollowing(FollowReport& r) const {
  std::ostringstream why;
  why.precision(2);
  if (std::isnan(r.gap_window_start)) {
    why << "the robot never came within " << settings_.gap_tolerance << " m of the follow "
        << "distance " << settings_.follow_distance << " m (final gap " << r.final_gap << " m)";
    r.failures.push_back(why.str());
    why.str("");
  } else if (r.gap_samples > 0 && r.gap_within_tolerance < settings_.min_gap_held) {
    why << "the gap was held " << 100.0 * r.gap_within_tolerance << " % of the walk (at least "
        << 100.0 * settings_.min_gap_held << " % expected; mean gap " << r.gap_mean << " m for "
        << settings_.follow_distance << " m)";
    r.failures.push_back(why.str());
    why.str("");
  }
  if (r.estimate_error_median > settings_.gap_tolerance) {
    why << "the estimate's median error was " << r.estimate_error_median
        << " m, more than the gap tolerance " << settings_.gap_tolerance
        << " m (calibrate the layout: doc/calibration.md)";
    r.failures.push_back(why.str());
    why.str("");
  }
  if (r.min_gap_while_moving < settings_.safe_distance) {
    why << "the robot came to " << r.min_gap_while_moving << " m of the person while moving, "
        << "closer than safe_distance " << settings_.safe_distance
        << " m (uncalibrated modules that read long stop it late: doc/calibration.md)";
    r.failures.push_back(why.str());
  }
}

FollowReport FollowMetrics::report() const {
  FollowReport r;
  r.min_gap = std::numeric_limits<double>::infinity();
  r.min_gap_while_moving = std::numeric_limits<double>::infinity();
  r.min_clearance = min_clearance_;
  r.collided = !std::isnan(collision_time_);
  r.collision_time = collision_time_;
  if (samples_.empty()) {
    r.failures.push_back("nothing was sampled (no odometry, ground truth or estimate heard)");
    return r;
  }
  r.duration = samples_.back().t - samples_.front().t;
  r.final_gap = std::hypot(samples_.back().target_x - samples_.back().robot_x,
                           samples_.back().target_y - samples_.back().robot_y);
  std::vector<double> gaps_in_window;
  std::vector<double> errors;
  std::vector<double> nees;
  std::map<std::string, int> status_counts;
  int within = 0;
  bool caught_up = false;
  r.gap_window_start = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const FollowSample& s = samples_[i];
    if (i > 0) {
      const FollowSample& p = samples_[i - 1];
      r.robot_distance += std::hypot(s.robot_x - p.robot_x, s.robot_y - p.robot_y);
      r.target_distance += std::hypot(s.target_x - p.target_x, s.target_y - p.target_y);
    }
    const double gap = std::hypot(s.target_x - s.robot_x, s.target_y - s.robot_y);
    r.min_gap = std::min(r.min_gap, gap);
    const bool moving = std::abs(s.cmd_linear) > settings_.moving_command;
    if (moving) {
      r.min_gap_while_moving = std::min(r.min_gap_while_moving, gap);
    }
    const bool within_now = std::abs(gap - settings_.follow_distance) <= settings_.gap_tolerance;
    if (!caught_up && s.t - samples_.front().t >= settings_.settle_time && within_now) {
      caught_up = true;
      r.gap_window_start = s.t - samples_.front().t;
    }
    const bool walking =
        s.target_speed > kStandingSpeed && s.target_speed < settings_.robot_max_speed;
    if (caught_up && walking) {
      gaps_in_window.push_back(gap);
      within += within_now;
    }
    ++status_counts[s.estimate_status];
    if (s.estimate_x && s.estimate_y) {
      errors.push_back(std::hypot(*s.estimate_x - s.truth_x, *s.estimate_y - s.truth_y));
      if (s.estimate_covariance) {
        const auto& c = *s.estimate_covariance;
        Eigen::Matrix2d p;
        p << c[0], c[1], c[1], c[2];
        if (const auto v =
                nees2d(Eigen::Vector2d(*s.estimate_x - s.truth_x, *s.estimate_y - s.truth_y), p)) {
          nees.push_back(*v);
        }
      }
    }
  }
  r.gap_samples = static_cast<int>(gaps_in_window.size());
  r.gap_within_tolerance = gaps_in_window.empty() ? 0.0 : double(within) / gaps_in_window.size();
  r.gap_mean = mean(gaps_in_window);
  r.estimate_availability = double(errors.size()) / samples_.size();
  for (const auto& [status, count] : status_counts) {
    r.estimate_status_share[status] = double(count) / samples_.size();
  }
  r.estimate_error_median = quantile(errors, 0.5);
  r.estimate_error_p95 = quantile(errors, 0.95);
  r.estimate_error_mean = mean(errors);
  r.estimate_nees_median = quantile(nees, 0.5);
  r.estimate_within_95 = shareInside95(nees);

  std::vector<double> deviations;
  const std::vector<PathPoint> path = buildPath(samples_, settings_);
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const FollowSample& s = samples_[k];
    // Like the gap, the path is judged while following: the path recorded while the robot
    // caught up from its start was estimated from farther away.
    if (!(s.t - samples_.front().t >= r.gap_window_start)) {
      continue;
    }
    double best = std::numeric_limits<double>::infinity();
    std::size_t best_segment = 0;
    double best_param = 0.0;
    for (std::size_t j = 0; j + 1 < path.size() && path[j + 1].sample <= k; ++j) {
      const double ax = path[j].x, ay = path[j].y;
      const double dx = path[j + 1].x - ax, dy = path[j + 1].y - ay;
      const double len2 = dx * dx + dy * dy;
      const double u = std::clamp(((s.robot_x - ax) * dx + (s.robot_y - ay) * dy) / len2, 0.0, 1.0);
      const double d = std::hypot(s.robot_x - (ax + u * dx), s.robot_y - (ay + u * dy));
      if (d < best) {
        best = d;
        best_segment = j;
        best_param = u;
      }
    }
    // Not yet on the path (behind its first point) or no path yet: no deviation to speak of.
    if (!std::isfinite(best) || (best_segment == 0 && best_param == 0.0)) {
      continue;
    }
    if (path[best_segment].turn || path[best_segment + 1].turn) {
      continue;
    }
    deviations.push_back(best);
  }
  const FollowSample& first = samples_.front();
  const bool had_to_move =
      r.target_distance > 1.0 ||
      std::hypot(first.target_x - first.robot_x, first.target_y - first.robot_y) >
          settings_.follow_distance + settings_.gap_tolerance;
  if (had_to_move && r.robot_distance < settings_.min_robot_distance) {
    std::ostringstream why;
    why.precision(3);
    why << "the robot never moved (" << r.robot_distance << " m in " << r.duration
        << " s while the target walked " << r.target_distance << " m)";
    r.failures.push_back(why.str());
  }
  if (errors.empty()) {
    r.failures.push_back("the estimate never became usable (no OK or DEGRADED estimate)");
  }
  if (settings_.judge_following && had_to_move) {
    judgeFollowing(r);
  }
  r.path_samples = static_cast<int>(deviations.size());
  r.path_deviation_median = quantile(deviations, 0.5);
  r.path_deviation_max = deviations.empty()
                             ? std::numeric_limits<double>::quiet_NaN()
                             : *std::max_element(deviations.begin(), deviations.end());
  return r;
}

std::string FollowReport::toJson() const {
  std::ostringstream out;
  out << "{\n"
      << "  \"duration_s\": " << jsonNumber(duration) << ",\n"
      << "  \"robot_distance_m\": " << jsonNumber(robot_distance) << ",\n"
      << "  \"target_distance_m\": " << jsonNumber(target_distance) << ",\n"
      << "  \"min_gap_m\": " << jsonNumber(min_gap) << ",\n"
      << "  \"min_gap_while_moving_m\": " << jsonNumber(min_gap_while_moving) << ",\n"
      << "  \"final_gap_m\": " << jsonNumber(final_gap) << ",\n"
      << "  \"gap_mean_m\": " << jsonNumber(gap_mean) << ",\n"
      << "  \"gap_within_tolerance\": " << jsonNumber(gap_within_tolerance) << ",\n"
      << "  \"gap_samples\": " << gap_samples << ",\n"
      << "  \"gap_window_start_s\": " << jsonNumber(gap_window_start) << ",\n"
      << "  \"estimate_availability\": " << jsonNumber(estimate_availability) << ",\n"
      << "  \"estimate_status_share\": {";
  bool first = true;
  for (const auto& [status, share] : estimate_status_share) {
    out << (first ? "" : ", ") << jsonString(status) << ": " << jsonNumber(share);
    first = false;
  }
  out << "},\n"
      << "  \"estimate_error_median_m\": " << jsonNumber(estimate_error_median) << ",\n"
      << "  \"estimate_error_p95_m\": " << jsonNumber(estimate_error_p95) << ",\n"
      << "  \"estimate_error_mean_m\": " << jsonNumber(estimate_error_mean) << ",\n"
      << "  \"estimate_nees_median\": " << jsonNumber(estimate_nees_median) << ",\n"
      << "  \"estimate_within_95\": " << jsonNumber(estimate_within_95) << ",\n"
      << "  \"path_deviation_median_m\": " << jsonNumber(path_deviation_median) << ",\n"
      << "  \"path_deviation_max_m\": " << jsonNumber(path_deviation_max) << ",\n"
      << "  \"path_samples\": " << path_samples << ",\n"
      << "  \"min_clearance_m\": " << jsonNumber(min_clearance) << ",\n"
      << "  \"collided\": " << (collided ? "true" : "false") << ",\n"
      << "  \"collision_time_s\": " << jsonNumber(collision_time) << ",\n"
      << "  \"passed\": " << (failures.empty() ? "true" : "false") << ",\n"
      << "  \"failures\": [";
  for (std::size_t i = 0; i < failures.size(); ++i) {
    out << (i == 0 ? "" : ", ") << jsonString(failures[i]);
  }
  out << "]\n"
      << "}\n";
  return out.str();
}

std::string FollowMetrics::toCsv() const {
  std::ostringstream out;
  out.precision(9);
  out << "t,robot_x,robot_y,robot_yaw,robot_speed,cmd_linear,cmd_angular,target_x,target_y,"
         "target_speed,truth_x,truth_y,estimate_x,estimate_y\n";
  for (const auto& s : samples_) {
    out << s.t << ',' << s.robot_x << ',' << s.robot_y << ',' << s.robot_yaw << ',' << s.robot_speed
        << ',' << s.cmd_linear << ',' << s.cmd_angular << ',' << s.target_x << ',' << s.target_y
        << ',' << s.target_speed << ',' << s.truth_x << ',' << s.truth_y << ',';
    if (s.estimate_x && s.estimate_y) {
      out << *s.estimate_x << ',' << *s.estimate_y;
    } else {
      out << ',';
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace control
}  // namespace radio_follow
