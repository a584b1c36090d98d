// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "radio_follow/common/target_status.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/correlated_error.hpp"
#include "radio_follow/estimation/particle_filter.hpp"
#include "radio_follow/estimation/tracked_reading.hpp"

namespace radio_follow {
namespace estimation {

/// Two AoA boards of one kind facing opposite ways: seed 001's pair of opposed directional
/// antennas (Sections 3-4). A tag in front of `a` is behind `b`, where the board reads
/// weaker, so the RSSI difference of the two says which side of the pair the tag is on,
/// which an array's angle cannot (it sees front and back alike).
struct RssPair {
  std::size_t a = 0;  ///< layout index of the board whose forward axis is the pair's
  std::size_t b = 0;  ///< layout index of the opposed board
  /// Midpoint of the two boards, robot frame, m: directions are taken from here.
  Eigen::Vector3d midpoint = Eigen::Vector3d::Zero();
  /// Yaw of `a`'s forward axis (its x axis projected on the xy-plane), robot frame, rad.
  double axis_yaw = 0.0;
};

/// Forward axes within this of exactly opposite make a pair, rad (20 deg).
double rssPairTolerance();

/// The opposed pairs of a layout's boards. A pair is two boards of the same kind (the two
/// kinds' RSSI levels differ by about 10 dB, Tables 3.2-3.7) whose forward axes, projected
/// on the xy-plane, are within rssPairTolerance() of opposite. Each board joins at most
/// one pair: boards are taken in layout order, each paired with the not yet paired later
/// board closest to opposite. Spot and cube give front/back and left/right.
std::vector<RssPair> opposedBoardPairs(const std::vector<AoaBoard>& boards);

/// Seed 001's direction likelihood (eqs 3-4 give the direction from the differences of
/// two opposed pairs; its eqs 6-8 weigh particles by it) as a likelihood of one pair's
/// difference d = rssi_a - rssi_b, dB:
///   l(d | theta) = (1 - eps) N(d; g cos(theta - theta_a), sigma^2) + eps / W,
/// theta the particle's direction from the pair's midpoint, theta_a the pair's axis. The
/// cosine is the first harmonic of an antenna pattern whose front reads g/2 above its
/// mean and whose back g/2 below, so `g` is the difference with the tag straight ahead of
/// `a`: one board's front-to-back drop. The uniform share eps over W dB keeps every
/// particle alive under any difference (a reflection, a body in the way).
struct RssDirectionLikelihood {
  double gain = 6.0;            ///< g, dB
  double sigma = 8.0;           ///< sigma of the difference, dB
  double outlier_share = 0.05;  ///< eps
  double floor_width = 60.0;    ///< W, dB

  /// l(d | theta) with `cos_offset` = cos(theta - theta_a).
  double operator()(double difference, double cos_offset) const;
};

/// Weighs `filter`'s particles by one pair's difference: `midpoint` of the pair and
/// `axis_yaw` of its forward board in the tracking frame; each particle's direction is
/// taken in the xy-plane.
MeasurementFit weighRssDirection(ParticleFilter& filter, const Eigen::Vector3d& midpoint,
                                 double axis_yaw, double difference,
                                 const RssDirectionLikelihood& model);

/// One opposed pair's RSSI difference (`pair` indexes opposedBoardPairs()), as the
/// particle tracker takes it: which side, not where. It weighs the hypotheses the other
/// readings place, places none itself, and counts with the bearings' source bit.
struct RssDirectionReading {
  static constexpr std::uint8_t kSource = kSourceAoa;
  static constexpr bool kFixesDistance = false;
  static constexpr ColdSeed kColdSeed = ColdSeed::kNone;
  static constexpr const char* kTopicsParam = nullptr;  ///< formed by the locator, no topic
  struct Tuning {
    bool enabled = false;  ///< rss_direction: an optional input
    RssDirectionLikelihood likelihood;
  };
  static std::size_t expectedSensors(const Layout& /*layout*/) { return 0; }
  SensorPair sensors() const { return {pair, 0}; }
  std::optional<SensorPair> heardAs() const { return std::nullopt; }

  std::size_t pair = 0;
  double difference = 0.0;  ///< rssi_a - rssi_b, dB
};

MeasurementFit weigh(const RssDirectionReading& r, ParticleFilter& filter, const TrackerContext& c);
/// Nothing: a side is no position error.
inline std::optional<InformingSensor> informing(const RssDirectionReading& /*r*/,
                                                const Eigen::Vector3d& /*position*/,
                                                const TrackerContext& /*c*/) {
  return std::nullopt;
}
inline Decorrelation decorrelation(const RssDirectionReading& /*r*/, const TrackerContext& /*c*/) {
  return {};
}
/// An optional input (rss_direction), and only of a pair the layout has.
bool usable(const RssDirectionReading& r, const TrackerContext& c);
/// Refused: the particle estimator forms these from the bearings' RSSI; no sensor sends one.
inline Intake accept(RssDirectionReading& /*r*/, const LocatorIntake& /*c*/) {
  return Intake::kRefused;
}
inline void observe(const RssDirectionReading& /*r*/, double /*t*/, const LocatorIntake& /*c*/,
                    FreshMeasurements& /*fresh*/, LocatorEstimate& /*out*/) {}

/// One pair's RSSI difference, formed from one reading of each board.
struct RssDifference {
  std::size_t pair = 0;     ///< index into the pairs
  double difference = 0.0;  ///< rssi_a - rssi_b, dB
  double t = 0.0;           ///< the newer reading's stamp, s
};

/// Forms the pairs' differences from the boards' RSSI readings as they arrive. A reading
/// waits for one of the opposed board within `window`; each reading is used once, so
/// consecutive differences share no reading and their evidence is independent.
class RssDifferencer {
 public:
  RssDifferencer(const std::vector<AoaBoard>& boards, double window = 0.1);

  /// Records board `board`'s RSSI (dBm) at `t`; the pair's difference when the opposed
  /// board has an unused reading within the window.
  std::optional<RssDifference> add(std::size_t board, double rssi, double t);
  void reset();
  const std::vector<RssPair>& pairs() const { return pairs_; }

 private:
  struct Reading {
    double rssi = 0.0;
    double t = 0.0;
    bool unused = false;
  };
  std::vector<RssPair> pairs_;
  /// Per board: its pair, or none.
  std::vector<std::optional<std::size_t>> pair_of_;
  std::vector<Reading> newest_;
  double window_;
};

}  // namespace estimation
}  // namespace radio_follow
