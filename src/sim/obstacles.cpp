// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/obstacles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/geometry.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace sim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Ray (origin o, unit direction d) against a circle: the nearest t >= 0, or inf.
double hitCircle(double ox, double oy, double dx, double dy, const CircleObstacle& c) {
  const double fx = ox - c.x;
  const double fy = oy - c.y;
  const double b = fx * dx + fy * dy;
  const double cc = fx * fx + fy * fy - c.radius * c.radius;
  const double disc = b * b - cc;
  if (disc < 0.0) {
    return kInf;
  }
  const double root = std::sqrt(disc);
  const double t1 = -b - root;
  const double t2 = -b + root;
  if (t1 >= 0.0) {
    return t1;
  }
  return t2 >= 0.0 ? 0.0 : kInf;  // inside the circle: touching it
}

/// Ray against a segment: the t >= 0 of the crossing, or inf.
double hitWall(double ox, double oy, double dx, double dy, const WallObstacle& w) {
  const double ex = w.x2 - w.x1;
  const double ey = w.y2 - w.y1;
  const double denom = dx * ey - dy * ex;
  if (std::abs(denom) < 1e-12) {
    return kInf;  // parallel
  }
  const double qx = w.x1 - ox;
  const double qy = w.y1 - oy;
  const double t = (qx * ey - qy * ex) / denom;
  const double u = (qx * dy - qy * dx) / denom;
  return t >= 0.0 && u >= 0.0 && u <= 1.0 ? t : kInf;
}

}  // namespace

const ParamTable<ScanConfig>& ScanConfig::table() {
  using C = ScanConfig;
  constexpr double kDeg = deg2rad(1.0);
  static const ParamTable<C> t =
      ParamTable<C>()
          .add("scan/rate", &C::rate, "Hz",
               "Scans per second (published only when the scenario has obstacles).",
               Range::aboveUpTo(0.0, 100.0))
          .addScaled("scan/angle_min_deg", &C::angle_min, kDeg, "deg", "First beam's angle.",
                     Range::closed(-180.0, 180.0))
          .addScaled("scan/angle_max_deg", &C::angle_max, kDeg, "deg",
                     "Last beam's angle, > scan/angle_min_deg.", Range::closed(-180.0, 180.0))
          .add("scan/beams", &C::beams, "", "Beams per scan.", Range::closed(2, 100000))
          .add("scan/range_min", &C::range_min, "m", "Shortest range reported.",
               Range::atLeast(0.0))
          .add("scan/range_max", &C::range_max, "m",
               "Longest range reported, > scan/range_min; farther is no return.", Range::above(0.0))
          .add("scan/sigma", &C::sigma, "m", "Range noise.", Range::atLeast(0.0));
  return t;
}

void ScanConfig::load(const ParamSource& source) {
  table().load(source, *this);
}

void ScanConfig::validate() const {
  table().check(*this);
  require(angle_min < angle_max, "~scan/angle_max_deg", rad2deg(angle_max),
          "an angle > ~scan/angle_min_deg (" + std::to_string(rad2deg(angle_min)) + ")");
  require(range_max > range_min, "~scan/range_max", range_max,
          "a range > ~scan/range_min (" + std::to_string(range_min) + " m)");
}

double castRay(const Obstacles& obstacles, double x, double y, double angle) {
  const double dx = std::cos(angle);
  const double dy = std::sin(angle);
  double best = kInf;
  for (const auto& c : obstacles.circles) {
    best = std::min(best, hitCircle(x, y, dx, dy, c));
  }
  for (const auto& w : obstacles.walls) {
    best = std::min(best, hitWall(x, y, dx, dy, w));
  }
  return best;
}

std::vector<double> scanRanges(const Obstacles& obstacles, const ScanConfig& config,
                               const Pose2& pose) {
  std::vector<double> ranges(static_cast<std::size_t>(config.beams));
  const double step = config.angleIncrement();
  for (int i = 0; i < config.beams; ++i) {
    const double r = castRay(obstacles, pose.x, pose.y, pose.yaw + config.angle_min + i * step);
    ranges[static_cast<std::size_t>(i)] = r <= config.range_max ? r : kInf;
  }
  return ranges;
}

std::vector<float> noisyScan(const Obstacles& obstacles, const ScanConfig& config,
                             const Pose2& pose, std::normal_distribution<double>& noise,
                             std::mt19937_64& rng) {
  std::vector<float> ranges;
  for (const double r : scanRanges(obstacles, config, pose)) {
    ranges.push_back(static_cast<float>(std::isfinite(r) ? std::max(0.0, r + noise(rng)) : r));
  }
  return ranges;
}

double clearance(const Obstacles& obstacles, double x, double y) {
  double best = kInf;
  for (const auto& c : obstacles.circles) {
    best = std::min(best, std::hypot(x - c.x, y - c.y) - c.radius);
  }
  for (const auto& w : obstacles.walls) {
    best = std::min(best, distanceToSegment({x, y}, {w.x1, w.y1}, {w.x2, w.y2}));
  }
  return best;
}

}  // namespace sim
}  // namespace radio_follow
