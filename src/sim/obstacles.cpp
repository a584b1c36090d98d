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

void ScanConfig::load(const ParamSource& p) {
  p.param("scan/rate", rate, rate);
  double angle_min_deg = rad2deg(angle_min);
  double angle_max_deg = rad2deg(angle_max);
  p.param("scan/angle_min_deg", angle_min_deg, angle_min_deg);
  p.param("scan/angle_max_deg", angle_max_deg, angle_max_deg);
  angle_min = deg2rad(angle_min_deg);
  angle_max = deg2rad(angle_max_deg);
  p.param("scan/beams", beams, beams);
  p.param("scan/range_min", range_min, range_min);
  p.param("scan/range_max", range_max, range_max);
  p.param("scan/sigma", sigma, sigma);
}

void ScanConfig::validate() const {
  require(std::isfinite(rate) && rate > 0.0 && rate <= 100.0, "~scan/rate", rate,
          "a rate in (0, 100] Hz");
  require(std::isfinite(angle_min) && std::isfinite(angle_max) && angle_min < angle_max,
          "scan.angle_min", angle_min, "angle_min < angle_max, radians");
  require(beams >= 2 && beams <= 100000, "scan.beams", beams, "a beam count in [2, 100000]");
  require(range_min >= 0.0 && range_max > range_min, "scan.range_max", range_max,
          "range_max > range_min >= 0, metres");
  require(sigma >= 0.0, "scan.sigma", sigma, "a standard deviation >= 0 in m");
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
