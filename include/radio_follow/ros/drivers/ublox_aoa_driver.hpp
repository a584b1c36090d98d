// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <string>
#include <string_view>
#include <vector>

#include "radio_follow/AoaBearing.h"
#include "radio_follow/drivers/serial_line_params.hpp"
#include "radio_follow/drivers/ublox_aoa_params.hpp"
#include "radio_follow/drivers/uudf_decoder.hpp"
#include "radio_follow/ros/common/output_diagnostic.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/drivers/serial_line_driver.hpp"

namespace radio_follow {

/// Driver for a u-blox XPLR-AOA-1 / ANT-B10 antenna board running u-connectLocate.
/// Publishes `bearing` (AoaBearing) for every +UUDF event of an accepted tag, and sends
/// `init_commands` on every (re)connect. Port, framing, counting, reconnects, diagnostics
/// and the delivery queue are the QueuedSerialLineDriver's.
class UbloxAoaDriverNode : public QueuedSerialLineDriver<AoaBearing> {
 public:
  /// config/ublox_aoa_driver.yaml (drivers::UbloxAoaParams).
  using Params = drivers::UbloxAoaParams;

  UbloxAoaDriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  /// With `params` loaded and validated by the caller (layout_drivers: one driver per
  /// device of a layout in one process); `private_nh` holds the diagnostics settings.
  UbloxAoaDriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh, const Params& params);
  ~UbloxAoaDriverNode() override;

 private:
  std::string onOpened(double now) override;
  std::string onLine(std::string_view line, double stamp) override;
  void publish(AoaBearing& msg) override;

  bool accepted(const std::string& tag_id) const;
  AoaBearing message(double stamp) const;

  Params params_;
  ros::Publisher bearing_pub_;
  OutputDiagnostic* bearing_output_ = nullptr;  // the base's, ticked by the delivery thread
  drivers::UudfEvent event_;                    // guarded by mutex()
};

}  // namespace radio_follow
