// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "radio_follow/drivers/tdoa_grouper.hpp"

namespace radio_follow {
namespace drivers {

/// Speed of light in vacuum, m/s.
constexpr double kSpeedOfLight = 299792458.0;

/// A configured TDoA anchor.
struct TdoaAnchorConfig {
  std::string id;                                      ///< Name used in TdoaDifference.anchor_a/b.
  std::uint64_t address = 0;                           ///< 64-bit address in its reports.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< Fixed frame, metres.
};

/// Anchor layout and the parameters of the time-difference computation.
struct TdoaDifferenceConfig {
  std::vector<TdoaAnchorConfig> anchors;
  std::size_t master = 0;     ///< Index of the clock master (sync transmitter).
  std::size_t reference = 0;  ///< Index of the anchor every difference is taken against.
  /// Variance written into every difference, m^2 (the anchors' variance field has no
  /// documented unit).
  double distance_variance = 0.0225;
  /// A difference is physically bounded by the anchors' baseline; one exceeding it by
  /// more than this is discarded (a mis-grouped blink or a multipath outlier), metres.
  /// Whatever the baseline, a difference beyond kMaxDistanceDifference (300 m,
  /// plausibility.hpp) is discarded too.
  double plausibility_margin = 0.5;
  /// Fewest anchors (reference included) a blink needs to be published.
  std::size_t min_anchors = 2;

  /// Throws ParamError naming the first invalid field (names relative to the node's ~).
  void validate() const;
};

/// One distance difference |p - a| - |p - b| with b the reference anchor.
struct TdoaDistanceDifference {
  std::size_t anchor_a = 0;
  std::size_t anchor_b = 0;
  double distance_difference = 0.0;  ///< Metres.
  double variance = 0.0;             ///< m^2.
};

/// Turns receive timestamps into distance differences against the reference anchor.
///
/// Anchors synchronise to the master's sync frames and so run late by the sync frame's
/// time of flight |a - master| / c; that constant is added back (as brozb/uwb_tdoa
/// does). Timestamp differences are taken modulo 2^40 ticks (the DW1000 counter width,
/// 17.2 s), which is right both for 40-bit wrapping counters and for extended 64-bit
/// ones because a true difference is nanoseconds.
class TdoaDifferenceCalculator {
 public:
  /// Validates `config`; throws ParamError.
  explicit TdoaDifferenceCalculator(TdoaDifferenceConfig config);

  enum class Outcome {
    kOk,
    kNoReference,    ///< The reference anchor did not hear the blink.
    kTooFewAnchors,  ///< Fewer than min_anchors heard it.
    kNoPlausible,    ///< Every difference failed the plausibility bound.
  };

  /// Appends the group's differences to `out` (cleared first); `implausible` (if given)
  /// is increased by the number of discarded differences. Every difference appended is
  /// finite, within the bounds above, and carries a finite positive variance (the
  /// configured one, checked by validate()).
  Outcome compute(const TdoaBlinkGroup& group, std::vector<TdoaDistanceDifference>* out,
                  std::uint64_t* implausible = nullptr) const;

  const TdoaDifferenceConfig& config() const { return config_; }

  /// Signed difference a - b of two tick counts, modulo 2^40.
  static std::int64_t tickDifference(std::uint64_t a, std::uint64_t b);

 private:
  TdoaDifferenceConfig config_;
  std::vector<double> sync_delay_;  // |a - master| / c, seconds
  std::vector<double> baseline_;    // |a - reference|, metres
};

}  // namespace drivers
}  // namespace radio_follow
