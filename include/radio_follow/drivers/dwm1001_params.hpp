// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "radio_follow/common/param_source.hpp"
#include "radio_follow/common/param_table.hpp"
#include "radio_follow/drivers/serial_line_params.hpp"

namespace radio_follow::drivers {

/// The dwm1001_driver node's parameters (config/dwm1001_driver.yaml,
/// doc/nodes/dwm1001_driver.md): the serial line's and the module's own.
struct Dwm1001Params : SerialLineParams {
  bool configure = true;            ///< run the shell dialogue; false = only listen
  std::string output_mode = "lec";  ///< "lec" or "les"
  std::string tag_id;               ///< used when configure is false ("" = unknown)
  std::string frame_id;             ///< "" = "uwb_<tag id>"
  std::string network_frame_id = "uwb_network";
  double shell_timeout = 2.0;  ///< s per dialogue step before it restarts

  /// SerialLineParams::table() and the module's entries.
  static const ParamTable<Dwm1001Params>& table();
  /// Absent keys keep their value; tag_id is normalised (upper case).
  void load(const ParamSource& source);
  /// Throws ParamError naming the first unusable parameter.
  void validate() const;
};

}  // namespace radio_follow::drivers
