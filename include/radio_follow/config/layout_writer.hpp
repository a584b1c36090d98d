// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"

namespace radio_follow {

/// What a calibration changes in a layout; every other field stays as it was.
struct LayoutCalibrationUpdate {
  /// New `twr_modules[].calibration` by module ID (normalised), lowest order first.
  std::map<std::string, std::vector<double>> range_calibration;
  /// Yaw offsets by board ID, rad: the board is mounted rotated by this much about its
  /// own z axis from the layout's `rpy_deg` (estimation::YawOffsetFit::yaw_offset).
  std::map<std::string, double> yaw_offset;
  /// Elevation offsets by board ID, rad (AoaBoard::elevation_offset), written as
  /// `elevation_offset_deg`.
  std::map<std::string, double> elevation_offset;
};

/// The orientation [roll, pitch, yaw] (deg, the layout's convention R = Rz Ry Rx) of a
/// board at `rpy_deg` turned by `yaw_offset` rad about its own z axis (R * Rz(offset)).
/// For a level board (roll and pitch 0, or upside down) only the yaw changes: by
/// +offset, or -offset upside down. Yaw wrapped to (-180, 180].
Eigen::Vector3d rpyWithYawOffset(const Eigen::Vector3d& rpy_deg, double yaw_offset);

/// The layout YAML `yaml_text` with `update` applied, re-emitted: keys in their order,
/// flow and block style and quoted strings kept, comments not (YAML parsers drop them);
/// `header_comment` lines are written first, each prefixed "# ". The result is checked
/// with parseLayout. Throws ParamError when the text is not a valid layout or the update
/// names a module or board the layout does not have; `origin` names the source.
std::string writeCalibratedLayout(const std::string& yaml_text, const std::string& origin,
                                  const LayoutCalibrationUpdate& update,
                                  const std::vector<std::string>& header_comment);

/// [roll, pitch, yaw] in degrees of a rotation, the layout's convention R = Rz Ry Rx.
Eigen::Vector3d rpyDegrees(const Eigen::Matrix3d& rotation);

/// A whole layout as YAML the locator loads (parseLayout), one sensor per flow-style line
/// like the shipped config/layouts/*.yaml; `header_comment` lines first, each prefixed "# ".
/// Numbers to six significant digits. The result is checked with parseLayout.
std::string writeLayout(const Layout& layout, const std::vector<std::string>& header_comment);

}  // namespace radio_follow
