// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/rss_direction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/estimation/particle_tracker.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// A board whose forward axis is nearly vertical has no direction in the plane.
constexpr double kMinHorizontal = 0.5;

}  // namespace

double rssPairTolerance() {
  return deg2rad(20.0);
}

std::vector<RssPair> opposedBoardPairs(const std::vector<AoaBoard>& boards) {
  std::vector<std::optional<double>> yaw(boards.size());
  for (std::size_t i = 0; i < boards.size(); ++i) {
    const Eigen::Vector3d forward = boards[i].orientation * Eigen::Vector3d::UnitX();
    if (forward.head<2>().norm() >= kMinHorizontal) {
      yaw[i] = std::atan2(forward.y(), forward.x());
    }
  }
  std::vector<bool> paired(boards.size(), false);
  std::vector<RssPair> pairs;
  for (std::size_t i = 0; i < boards.size(); ++i) {
    if (paired[i] || !yaw[i]) {
      continue;
    }
    std::optional<std::size_t> best;
    double best_offset = std::numeric_limits<double>::infinity();
    for (std::size_t j = i + 1; j < boards.size(); ++j) {
      if (paired[j] || !yaw[j] || boards[j].kind != boards[i].kind) {
        continue;
      }
      // How far from exactly opposite the two forward axes are.
      const double offset = std::abs(wrapAngle(*yaw[j] - *yaw[i] - kPi));
      if (offset <= rssPairTolerance() && offset < best_offset) {
        best = j;
        best_offset = offset;
      }
    }
    if (best) {
      paired[i] = paired[*best] = true;
      RssPair p;
      p.a = i;
      p.b = *best;
      p.midpoint = 0.5 * (boards[i].position + boards[*best].position);
      p.axis_yaw = *yaw[i];
      pairs.push_back(p);
    }
  }
  return pairs;
}

double RssDirectionLikelihood::operator()(double difference, double cos_offset) const {
  const double z = (difference - gain * cos_offset) / sigma;
  return (1.0 - outlier_share) * std::exp(-0.5 * z * z) / (std::sqrt(2.0 * kPi) * sigma) +
         outlier_share / floor_width;
}

RssDifferencer::RssDifferencer(const std::vector<AoaBoard>& boards, double window)
    : pairs_(opposedBoardPairs(boards)),
      pair_of_(boards.size()),
      newest_(boards.size()),
      window_(window) {
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    pair_of_[pairs_[k].a] = k;
    pair_of_[pairs_[k].b] = k;
  }
}

void RssDifferencer::reset() {
  for (Reading& r : newest_) {
    r.unused = false;
  }
}

std::optional<RssDifference> RssDifferencer::add(std::size_t board, double rssi, double t) {
  if (board >= newest_.size() || !pair_of_[board] || !std::isfinite(rssi) || !std::isfinite(t)) {
    return std::nullopt;
  }
  newest_[board] = Reading{rssi, t, true};
  const std::size_t k = *pair_of_[board];
  const RssPair& pair = pairs_[k];
  Reading& own = newest_[board];
  Reading& other = newest_[board == pair.a ? pair.b : pair.a];
  if (!other.unused || std::abs(other.t - t) > window_) {
    return std::nullopt;
  }
  own.unused = false;
  other.unused = false;
  const double rssi_a = board == pair.a ? own.rssi : other.rssi;
  const double rssi_b = board == pair.a ? other.rssi : own.rssi;
  return RssDifference{k, rssi_a - rssi_b, std::max(own.t, other.t)};
}

MeasurementFit weighRssDirection(ParticleFilter& filter, const Eigen::Vector3d& midpoint,
                                 double axis_yaw, double difference,
                                 const RssDirectionLikelihood& m) {
  const Eigen::Vector3d centre = midpoint - filter.origin();
  const Eigen::ArrayXd dx = filter.localX().cast<double>() - centre.x();
  const Eigen::ArrayXd dy = filter.localY().cast<double>() - centre.y();
  // cos(theta - theta_a) of every particle; one on the midpoint itself says nothing.
  const Eigen::ArrayXd cos_offset = (dx * std::cos(axis_yaw) + dy * std::sin(axis_yaw)) /
                                    (dx.square() + dy.square()).sqrt().max(1e-9);
  const Eigen::ArrayXd z = (difference - m.gain * cos_offset) / m.sigma;
  Eigen::ArrayXf& inlier = filter.workspace().inlier;
  inlier = ((1.0 - m.outlier_share) / (std::sqrt(2.0 * kPi) * m.sigma) * (-0.5 * z.square()).exp())
               .cast<float>();
  return filter.applyLikelihood(inlier, m.outlier_share / m.floor_width);
}

MeasurementFit weigh(const RssDirectionReading& r, ParticleFilter& filter,
                     const TrackerContext& c) {
  const RssPair& pair = c.rss_pairs[r.pair];
  return weighRssDirection(filter, c.pose.toFixed(pair.midpoint), c.pose.yaw + pair.axis_yaw,
                           r.difference, c.config.of<RssDirectionReading>().likelihood);
}

bool usable(const RssDirectionReading& r, const TrackerContext& c) {
  return c.config.of<RssDirectionReading>().enabled && r.pair < c.rss_pairs.size();
}

}  // namespace estimation
}  // namespace radio_follow
