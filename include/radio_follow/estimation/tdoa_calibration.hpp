// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "radio_follow/config/layout.hpp"

namespace radio_follow {
namespace estimation {

/// How the TDoA anchors' offsets are learnt from the robot's own UWB modules
/// (doc/nodes/locator.md, "TDoA auto-calibration").
struct TdoaCalibrationConfig {
  /// Learn the offsets and fuse the target's differences only once its pair has one.
  /// Takes effect only when the layout has TWR modules (the blinking sources).
  bool enabled = true;
  /// Seconds of the modules' blinks each pair's offset is the median of: the median of n
  /// blinks of sigma 0.3 m (1 ns) is good to about 0.37 m / sqrt(n), 2 cm over 30 s of
  /// one module at 10 Hz. A drift over seconds no window of such blinks can follow.
  double window = 30.0;
  /// Calibration differences a pair needs within the window before its offset is used
  /// (50: 5 s of one module, about 5 cm).
  int min_blinks = 50;

  /// Throws ParamError naming the field (the locator's parameter names).
  void validate() const;
};

/// The TDoA anchors' offsets, learnt online from the blinks of the robot's own TWR
/// modules (as the thesis's reference locator does). The anchors hear every UWB frame,
/// the modules' polls as well as the person's device's replies; a module sits at a known
/// position in the same frame as the anchors, so each of its differences
/// |m - a| - |m - b| is known, and what the anchors measure beyond it is the pair's
/// offset: a per-anchor antenna and clock-sync delay, common to every tag the pair
/// hears. Each pair's offset is the median of those residuals over a sliding window
/// (robust to the long outliers of a blocked path) and is subtracted from the target's
/// differences. Only an offset is fitted, not the reference's first-order polynomial:
/// the modules' known differences span a few decimetres at most, and a slope fitted
/// there would be extrapolated to the whole baseline. Time is double seconds; no ROS.
class TdoaCalibration {
 public:
  /// A pair's state for diagnostics.
  struct Pair {
    std::size_t a = 0;  ///< index into Layout::tdoa_anchors
    std::size_t b = 0;
    std::size_t samples = 0;       ///< residuals within the window
    std::optional<double> offset;  ///< m, once `samples` >= min_blinks
  };

  TdoaCalibration(const Layout& layout, const TdoaCalibrationConfig& config);

  /// Applies new settings; the residuals collected so far are kept.
  void setConfig(const TdoaCalibrationConfig& config);

  /// Whether the target's differences must be corrected (enabled, with TWR modules and
  /// at least two anchors in the layout).
  bool active() const;

  /// The TWR module (index into Layout::twr_modules) whose blinks `tag_id` are, any case.
  std::optional<std::size_t> moduleOf(const std::string& tag_id) const;

  /// One difference d = |m - a| - |m - b| (+ offset) of module `module`'s blink, anchors
  /// by index. False (nothing kept) for an unknown index, a != b violated or a value
  /// that is not finite.
  bool add(std::size_t module, std::size_t a, std::size_t b, double difference, double t);

  /// The offset to subtract from a measured a - b difference, or nothing while the pair
  /// has fewer than min_blinks residuals in its window.
  std::optional<double> offset(std::size_t a, std::size_t b) const;

  /// Every pair seen so far, in the order and orientation first seen (the driver's:
  /// a = an anchor, b = the reference).
  std::vector<Pair> pairs() const;

 private:
  struct Window {
    std::size_t a;
    std::size_t b;
    std::deque<std::pair<double, double>> residuals;  ///< (stamp, residual), stamp order
    double newest = 0.0;
    std::optional<double> offset;  ///< median of residuals when enough, cached on add
  };

  Window* find(std::size_t a, std::size_t b);
  const Window* find(std::size_t a, std::size_t b) const;
  void refresh(Window& w) const;

  Layout layout_;
  TdoaCalibrationConfig config_;
  std::vector<Window> windows_;
};

}  // namespace estimation
}  // namespace radio_follow
