// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/tdoa_differences.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/plausibility.hpp"
#include "radio_follow/drivers/tdoa_packet.hpp"

namespace radio_follow {
namespace drivers {
namespace {

constexpr unsigned kTimestampBits = 40;

}  // namespace

void TdoaDifferenceConfig::validate() const {
  require(anchors.size() >= 2, "~anchors", anchors.size(), "at least two anchors");
  std::set<std::string> ids;
  std::set<std::uint64_t> addresses;
  for (std::size_t i = 0; i < anchors.size(); ++i) {
    const std::string name = "~anchors[" + std::to_string(i) + "]";
    require(!anchors[i].id.empty(), name + ".id", anchors[i].id, "a non-empty name");
    require(ids.insert(anchors[i].id).second, name + ".id", anchors[i].id, "a unique name");
    require(addresses.insert(anchors[i].address).second, name + ".address", anchors[i].address,
            "a unique address");
    const Eigen::Vector3d& p = anchors[i].position;
    require(plausibleCoordinate(p.x()) && plausibleCoordinate(p.y()) && plausibleCoordinate(p.z()),
            name + ".position",
            std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " + std::to_string(p.z()),
            "three finite coordinates within 10 km, m");
  }
  require(master < anchors.size(), "~master", master, "one of the anchors");
  require(reference < anchors.size(), "~reference", reference, "one of the anchors");
  require(plausibleVariance(distance_variance), "~distance_variance", distance_variance,
          "a positive variance in m^2");
  require(std::isfinite(plausibility_margin) && plausibility_margin >= 0.0, "~plausibility_margin",
          plausibility_margin, "a non-negative distance in metres");
  require(min_anchors >= 2 && min_anchors <= anchors.size(), "~min_anchors", min_anchors,
          "an anchor count in [2, number of anchors]");
}

TdoaDifferenceCalculator::TdoaDifferenceCalculator(TdoaDifferenceConfig config)
    : config_(std::move(config)) {
  config_.validate();
  const Eigen::Vector3d& master = config_.anchors[config_.master].position;
  const Eigen::Vector3d& reference = config_.anchors[config_.reference].position;
  for (const auto& anchor : config_.anchors) {
    sync_delay_.push_back((anchor.position - master).norm() / kSpeedOfLight);
    baseline_.push_back((anchor.position - reference).norm());
  }
}

std::int64_t TdoaDifferenceCalculator::tickDifference(std::uint64_t a, std::uint64_t b) {
  constexpr std::uint64_t kMask = (std::uint64_t{1} << kTimestampBits) - 1;
  constexpr std::uint64_t kHalf = std::uint64_t{1} << (kTimestampBits - 1);
  const std::uint64_t d = (a - b) & kMask;
  return d >= kHalf ? static_cast<std::int64_t>(d) - static_cast<std::int64_t>(kMask + 1)
                    : static_cast<std::int64_t>(d);
}

TdoaDifferenceCalculator::Outcome TdoaDifferenceCalculator::compute(
    const TdoaBlinkGroup& group, std::vector<TdoaDistanceDifference>* out,
    std::uint64_t* implausible) const {
  out->clear();
  if (group.receptions.size() < config_.min_anchors) {
    return Outcome::kTooFewAnchors;
  }
  const auto ref =
      std::find_if(group.receptions.begin(), group.receptions.end(),
                   [&](const TdoaReception& r) { return r.anchor == config_.reference; });
  if (ref == group.receptions.end()) {
    return Outcome::kNoReference;
  }
  for (const auto& r : group.receptions) {
    if (r.anchor == config_.reference) {
      continue;
    }
    // Differences of ticks first (exact integers), then seconds: converting absolute
    // 64-bit tick counts to double would lose the 15 ps resolution.
    const double dt =
        static_cast<double>(tickDifference(r.rx_ticks, ref->rx_ticks)) / kTdoaTickFrequency +
        (sync_delay_[r.anchor] - sync_delay_[config_.reference]);
    const double d = kSpeedOfLight * dt;
    // Bounded by the anchors' baseline, and in any case by the physical limit of a UWB
    // link (anchors further apart than that cannot both hear one blink).
    if (!plausibleDistanceDifference(d) ||
        std::abs(d) > baseline_[r.anchor] + config_.plausibility_margin) {
      if (implausible != nullptr) {
        ++*implausible;
      }
      continue;
    }
    out->push_back({r.anchor, config_.reference, d, config_.distance_variance});
  }
  return out->empty() ? Outcome::kNoPlausible : Outcome::kOk;
}

}  // namespace drivers
}  // namespace radio_follow
