// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "radio_follow/common/param_source.hpp"
#include "radio_follow/common/param_table.hpp"
#include "radio_follow/drivers/serial_line_params.hpp"

namespace radio_follow::drivers {

/// The ublox_aoa_driver node's parameters (config/ublox_aoa_driver.yaml,
/// doc/nodes/ublox_aoa_driver.md): the serial line's and the board's own.
struct UbloxAoaParams : SerialLineParams {
  std::string frame_id;                    ///< the board's frame, required
  std::vector<std::string> tag_ids;        ///< accepted tags (12 hex digits); empty = all
  bool invert_azimuth = true;              ///< publish counter-clockwise azimuth
  std::vector<std::string> init_commands;  ///< AT commands sent on every connect

  /// SerialLineParams::table() and the board's scalar entries (tag_ids and
  /// init_commands are lists, which a table does not hold).
  static const ParamTable<UbloxAoaParams>& table();
  /// Absent keys keep their value; tag IDs are upper-cased.
  void load(const ParamSource& source);
  /// Throws ParamError naming the first unusable parameter.
  void validate() const;
};

}  // namespace radio_follow::drivers
