// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <memory>
#include <string>
#include <vector>

#include "radio_follow/common/param_table.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/drivers/dwm1001_driver.hpp"
#include "radio_follow/ros/drivers/ublox_aoa_driver.hpp"

namespace radio_follow {

/// The serial drivers of a robot, read from its layout (the `layout_drivers` node that
/// launch/robot.launch starts): one Dwm1001DriverNode per `twr_modules` entry on
/// `uwb_port_prefix` + ID and one UbloxAoaDriverNode per `aoa_boards` entry on
/// `aoa_port_prefix` + ID (the udev symlinks of udev/99-radio-follow.rules), each in its
/// topic-convention namespace (uwb/<id>, aoa/<id>; conventionalTopics) with its own
/// reconnects, diagnostics and delivery queue. The settings every device of a kind shares
/// come from the private namespaces `dwm1001/` and `ublox_aoa/` (config/dwm1001_driver.yaml,
/// config/ublox_aoa_driver.yaml); port, ID, frame and the accepted Bluetooth tag come from
/// the layout, so they may not be set there.
class LayoutDriversNode {
 public:
  struct Params {
    std::string layout_file;
    std::string uwb_port_prefix = "/dev/dwm1001_";
    std::string aoa_port_prefix = "/dev/aoa_";

    /// layout_file and the port prefixes (the shared driver settings: their own tables).
    static const ParamTable<Params>& table();
    void load(const ParamReader& private_nh);
    void validate() const;
  };

  LayoutDriversNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);

  /// The device paths opened, in layout order (modules, then boards).
  const std::vector<std::string>& ports() const { return ports_; }

 private:
  std::vector<ros::NodeHandle> handles_;  // the drivers' namespaces, kept for their lifetime
  std::vector<std::unique_ptr<Dwm1001DriverNode>> modules_;
  std::vector<std::unique_ptr<UbloxAoaDriverNode>> boards_;
  std::vector<std::string> ports_;
};

/// The per-device settings of one layout module: `shared` (the `dwm1001/` namespace) with
/// the port, ID and frame of `module`. Throws ParamError when `shared` sets one of those.
Dwm1001DriverNode::Params moduleDriverParams(const Dwm1001DriverNode::Params& shared,
                                             const TwrModule& module,
                                             const std::string& port_prefix);
/// The same for one layout board; the layout's `target.aoa_tag_id` (when set) is the only
/// accepted tag unless `shared` lists its own `tag_ids`.
UbloxAoaDriverNode::Params boardDriverParams(const UbloxAoaDriverNode::Params& shared,
                                             const AoaBoard& board, const Layout& layout,
                                             const std::string& port_prefix);

}  // namespace radio_follow
