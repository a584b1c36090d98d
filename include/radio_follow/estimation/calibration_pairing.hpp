// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/calibration_fit.hpp"

namespace radio_follow {
namespace estimation {

/// Where the tag was at a time: one sample of a ground-truth system (the simulator's
/// ground_truth/target_relative, a motion-capture pose), in the layout's fixed frame.
struct TimedPosition {
  double t = 0.0;  ///< the sample's stamp, s
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

/// A tape-measured point the person stood still at, in the layout's fixed frame, during
/// [from, until] seconds from the recording's start.
struct TapePoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double from = 0.0;
  double until = 0.0;
};

/// Reads the tape-measured points of a YAML file's text: `points: [{position: [x, y, z],
/// from: s, until: s}, ...]`. Throws ParamError naming the field (`points[2].until`), the
/// value and what is expected: finite numbers, 0 <= from < until, windows that do not
/// overlap. `origin` names the file in messages.
std::vector<TapePoint> parseTapePoints(const std::string& yaml_text, const std::string& origin);

/// Reads a tape-points file; throws ParamError when it cannot be read.
std::vector<TapePoint> loadTapePointsFile(const std::string& path);

/// The reference a calibration compares the sensors with: a ground-truth track,
/// interpolated linearly to each measurement's stamp, or tape-measured points, looked up
/// by the measurement's time from the recording's start.
class CalibrationReference {
 public:
  /// `track` in any order (sorted here); a measurement farther than `max_gap` seconds from
  /// the nearest sample is not compared (the tag may have moved in between). Throws
  /// std::invalid_argument when the track is empty or `max_gap` is not positive.
  static CalibrationReference fromTrack(std::vector<TimedPosition> track, double max_gap);
  static CalibrationReference fromPoints(std::vector<TapePoint> points);

  enum class Lookup {
    kFound,
    kGap,       ///< ground truth: no sample within max_gap (dropped, counted)
    kNoWindow,  ///< tape points: between the windows, the person walking (ignored)
  };
  /// The tag's position for a measurement stamped `stamp` and recorded `since_start`
  /// seconds after the recording began (tape windows are read off the recording's clock,
  /// the one `rosbag info` and rqt_bag show, which need not be the drivers' clock).
  Lookup at(double stamp, double since_start, Eigen::Vector3d& position) const;

  bool isTrack() const { return points_.empty(); }

 private:
  CalibrationReference() = default;
  std::vector<TimedPosition> track_;
  double max_gap_ = 0.0;
  std::vector<TapePoint> points_;
};

/// One range or bearing of the recording, for the target's anchor or tag only.
struct CalibrationMeasurement {
  enum class Kind { kRange, kBearing } kind = Kind::kRange;
  std::string sensor;        ///< module ID / frame (UwbRanges), board frame / ID (AoaBearing)
  double stamp = 0.0;        ///< header stamp, s
  double since_start = 0.0;  ///< recording time from the bag's start, s
  double value = 0.0;        ///< raw range, m, or azimuth in the board frame, rad
  /// Bearings: the elevation in the board frame, rad; NaN: not recorded.
  double elevation = std::numeric_limits<double>::quiet_NaN();
};

/// Every sensor's samples paired with the reference, and what was not paired.
struct CalibrationSamples {
  std::map<std::string, std::vector<RangeSample>> ranges;      ///< by module ID
  std::map<std::string, std::vector<AzimuthSample>> azimuths;  ///< by board ID
  std::map<std::string, std::vector<ElevationSample>> elevations;  ///< by board ID
  std::size_t gap_dropped = 0;      ///< no reference sample within max_gap
  std::size_t outside_windows = 0;  ///< tape points: not in any window
  std::size_t outside_view = 0;     ///< bearings with the tag outside the board's field of view
  std::size_t unknown_sensor = 0;   ///< sensor not in the layout
  std::size_t non_finite = 0;       ///< NaN or infinite readings (one would void the fit)
};

/// True distance |tag - module| (3D, module position from the layout) and true azimuth
/// atan2(y, x) of the tag in the board frame (board pose from the layout), and its true
/// elevation when the bearing carries one, of every measurement the reference covers.
/// Bearings whose true direction lies outside the board's field_of_view are left out: the
/// locator does not trust them either, and a board facing away reports reflections there,
/// not an offset.
CalibrationSamples pairWithReference(const std::vector<CalibrationMeasurement>& measurements,
                                     const Layout& layout, const CalibrationReference& reference);

/// The fit of one module or board, or why there is none (the layout keeps its old value).
template <typename Fit>
struct SensorCalibration {
  std::string id;
  std::size_t paired = 0;  ///< samples paired with the reference
  std::optional<Fit> fit;
  std::string error;  ///< why not fitted: too few samples, too short a span, ...
};

struct LayoutCalibration {
  std::vector<SensorCalibration<RangeCalibrationFit>> modules;  ///< layout order
  std::vector<SensorCalibration<YawOffsetFit>> boards;          ///< layout order; empty: skipped
  std::vector<SensorCalibration<ElevationOffsetFit>> elevations;  ///< as `boards`
  std::size_t fitted() const;
};

/// Fits every module of the layout (fitRangeCalibration of `degree`) and, with
/// `fit_boards`, every board's yaw and elevation offsets (fitYawOffset,
/// fitElevationOffset). A sensor with fewer than
/// `min_samples` paired samples, or whose fit throws, gets an error instead of a fit.
LayoutCalibration fitLayoutCalibration(const CalibrationSamples& samples, const Layout& layout,
                                       int degree, std::size_t min_samples, bool fit_boards);

/// The tag's true azimuth in a board's frame, rad (counter-clockwise, 0 = boresight).
double trueAzimuth(const AoaBoard& board, const Eigen::Vector3d& tag);
/// The tag's true elevation in a board's frame, rad (towards the board's +z).
double trueElevation(const AoaBoard& board, const Eigen::Vector3d& tag);

}  // namespace estimation
}  // namespace radio_follow
