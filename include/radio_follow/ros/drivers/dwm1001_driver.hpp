// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <string>
#include <string_view>

#include "radio_follow/UwbRanges.h"
#include "radio_follow/UwbTagLocation.h"
#include "radio_follow/drivers/dwm1001_decoder.hpp"
#include "radio_follow/drivers/dwm1001_params.hpp"
#include "radio_follow/drivers/dwm1001_shell.hpp"
#include "radio_follow/drivers/serial_line_params.hpp"
#include "radio_follow/ros/common/output_diagnostic.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/drivers/serial_line_driver.hpp"

namespace radio_follow {

/// The messages of one DWM1001 output line: built on the I/O thread, published on the
/// delivery queue's.
struct Dwm1001Output {
  bool has_ranges = false;
  UwbRanges ranges;
  bool has_location = false;
  UwbTagLocation location;
};

/// Driver for a Qorvo DWM1001 module in tag mode on its UART shell. Publishes
/// `ranges` (UwbRanges) for every output line and `tag_location` (UwbTagLocation) when
/// the line carried the module's own position. With `configure` it runs the shell
/// dialogue (Dwm1001Shell) on every (re)connect and stops the stream on shutdown. Port,
/// framing, counting, reconnects, diagnostics and the delivery queue are the
/// QueuedSerialLineDriver's.
class Dwm1001DriverNode : public QueuedSerialLineDriver<Dwm1001Output> {
 public:
  /// config/dwm1001_driver.yaml (drivers::Dwm1001Params).
  using Params = drivers::Dwm1001Params;

  Dwm1001DriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  /// With `params` loaded and validated by the caller (layout_drivers: one driver per
  /// device of a layout in one process); `private_nh` holds the diagnostics settings.
  Dwm1001DriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh, const Params& params);
  ~Dwm1001DriverNode() override;

 private:
  std::string onOpened(double now) override;
  void onClosed() override;
  std::string onLine(std::string_view line, double stamp) override;
  std::string onPending(std::string_view pending, double now) override;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) override;
  void publish(Dwm1001Output& out) override;

  void decode(std::string_view line, double stamp);
  Dwm1001Output messages(double stamp) const;
  void onShellTimer(const ros::TimerEvent& event);
  const std::string& tagId() const;
  std::string frameId() const;

  Params params_;
  ros::Publisher ranges_pub_;
  ros::Publisher location_pub_;
  OutputDiagnostic* ranges_output_ = nullptr;  // the base's, ticked by the delivery thread
  OutputDiagnostic* location_output_ = nullptr;
  // Guarded by mutex() (I/O thread vs shell timer and diagnostics):
  drivers::Dwm1001Shell shell_;
  drivers::DwmMeasurement measurement_;
  ros::Timer shell_timer_;
};

}  // namespace radio_follow
