// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {

/// Height of the person's tag in a layout's fixed frame unless configured, m: on the
/// chest. The one default of every target_height (locator, solver, particle filter,
/// simulator, placement advisor, homing controller).
constexpr double kDefaultTargetHeight = 1.0;

/// A UWB DWM1001 module in tag mode mounted on the robot (two-way ranging).
struct TwrModule {
  /// Module ID as the driver reports it in UwbRanges.tag_id, e.g. "5722".
  std::string id;
  /// TF frame of the module; the driver's frame_id.
  std::string frame_id;
  /// Antenna position in the layout's fixed frame, metres.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// Range calibration polynomial, corrected = sum_k c[k] * r^k (metres).
  std::vector<double> calibration{0.0, 1.0};

  /// Applies the calibration polynomial (Horner) to a raw range.
  double correctRange(double raw_range) const;
};

/// Which u-blox antenna board (selects the simulator's measured noise tables).
enum class AoaBoardKind { kXplrAoa1, kAntB10 };

/// A Bluetooth AoA antenna board mounted on the robot.
struct AoaBoard {
  /// Board name, unique in the layout (also the driver's namespace in the launch files).
  std::string id;
  /// TF frame of the board: x along boresight, z up. Matches AoaBearing.header.frame_id.
  std::string frame_id;
  AoaBoardKind kind = AoaBoardKind::kXplrAoa1;
  /// Board position in the fixed frame, metres.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// Board orientation in the fixed frame (maps board-frame vectors to the fixed frame).
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  /// Half-angle of the cone around boresight in which bearings are trusted, radians.
  double field_of_view = 1.22;  // 70 deg: the thesis found the edges unusable.
  /// What the board's elevation reads off the true one, radians (reported minus true;
  /// real XPLR-AOA-1 boards read 2-11 deg low): the locator subtracts it. Fitted by
  /// calibrate_layout, 0 until then.
  double elevation_offset = 0.0;
};

/// Largest elevation offset a layout may carry, rad: beyond it a board is mounted tilted
/// (set its pitch in rpy_deg) or the number is a typo.
constexpr double kMaxElevationOffset = deg2rad(30.0);

/// A TDoA anchor with a known position in the fixed frame.
struct TdoaAnchor {
  std::string id;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

/// No sensor of the layout: an ID it does not have. The locator refuses (and counts) a
/// measurement of it.
inline constexpr std::size_t kNoSensor = std::numeric_limits<std::size_t>::max();

/// Where every radio sensor sits on the robot, and what the target carries.
/// Shared by the locator, the simulator and the placement advisor.
struct Layout {
  /// Frame every position is expressed in (on the robot), e.g. "base_link".
  std::string fixed_frame = "base_link";
  /// UWB anchor ID the target carries (UwbRange.anchor_id), e.g. "DA12".
  std::string target_anchor_id;
  /// Bluetooth tag ID the target carries (AoaBearing.tag_id); empty = any tag.
  std::string target_tag_id;
  /// ID the target's UWB device blinks with to TDoA anchors (TdoaMeasurements.tag_id):
  /// `target.tdoa_tag_id`, by default `target.uwb_anchor_id`. Only its measurements are
  /// the person's; other tags (the robot's own modules among them) are not.
  std::string target_tdoa_tag_id;
  std::vector<TwrModule> twr_modules;
  std::vector<AoaBoard> aoa_boards;
  std::vector<TdoaAnchor> tdoa_anchors;

  /// Throws ParamError naming the first invalid field.
  void validate() const;

  const TwrModule* findTwrModule(const std::string& id_or_frame) const;
  const AoaBoard* findAoaBoard(const std::string& id_or_frame) const;
  const TdoaAnchor* findTdoaAnchor(const std::string& id) const;
  /// A sensor's index in its list (what the locator takes), or kNoSensor.
  std::size_t twrModuleIndex(const std::string& id_or_frame) const;
  std::size_t aoaBoardIndex(const std::string& id_or_frame) const;
  std::size_t tdoaAnchorIndex(const std::string& id) const;
  /// Whether TDoA measurements of `tag_id` (any case) are the target's.
  bool isTargetTdoaTag(const std::string& tag_id) const;
};

/// Reads a layout from YAML text (see config/layouts/*.yaml for the format) and
/// validates it. Throws ParamError on any missing or invalid field; `origin` names
/// the source in messages (a file path, usually).
Layout parseLayout(const std::string& yaml_text, const std::string& origin);

/// Reads and validates a layout file. Throws ParamError naming `param` (the node's
/// parameter or the tool's flag that gave the path) when it cannot be read.
Layout loadLayoutFile(const std::string& path, const std::string& param = "~layout_file");

std::string toString(AoaBoardKind kind);

/// The robot's outline in the fixed frame's xy-plane, counter-clockwise: the layout has
/// no outline of its own, so this is the convex hull of every TWR module and AoA board
/// (TDoA anchors are off the robot), grown by `margin` metres on every side (the hull's
/// corners become `margin`-sided bevels). With fewer than one sensor, empty.
std::vector<Eigen::Vector2d> layoutFootprint(const Layout& layout, double margin);

/// The package's topic convention for a layout's sensors, relative to the robot's
/// namespace: `uwb/<module id>/ranges`, `aoa/<board id>/bearing` and, with TDoA anchors,
/// `tdoa/measurements`. The driver launch files and the simulator follow it, so nodes can
/// default their inputs to it.
struct SensorTopics {
  std::vector<std::string> uwb;
  std::vector<std::string> aoa;
  std::vector<std::string> tdoa;
};
SensorTopics conventionalTopics(const Layout& layout);
/// The IDs of the modules whose calibration is still the identity `[0, 1]` (never fitted).
std::vector<std::string> uncalibratedModules(const Layout& layout);

/// The namespace of a module's driver in that convention, `uwb/<id>`.
std::string uwbNamespace(const std::string& module_id);
/// The namespace of a board's driver in that convention, `aoa/<id>`.
std::string aoaNamespace(const std::string& board_id);

}  // namespace radio_follow
