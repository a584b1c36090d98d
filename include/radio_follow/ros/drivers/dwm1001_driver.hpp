// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "radio_follow/UwbRanges.h"
#include "radio_follow/UwbTagLocation.h"
#include "radio_follow/drivers/delivery_queue.hpp"
#include "radio_follow/drivers/driver_stats.hpp"
#include "radio_follow/drivers/dwm1001_decoder.hpp"
#include "radio_follow/drivers/dwm1001_shell.hpp"
#include "radio_follow/drivers/line_framer.hpp"
#include "radio_follow/drivers/serial_transport.hpp"
#include "radio_follow/ros/drivers/driver_diagnostics.hpp"
#include "radio_follow/ros/common/output_diagnostic.hpp"
#include "radio_follow/ros/common/params.hpp"

namespace radio_follow {

/// Driver for a Qorvo DWM1001 module in tag mode on its UART shell. Publishes
/// `ranges` (UwbRanges) for every output line and `tag_location` (UwbTagLocation) when
/// the line carried the module's own position. With `configure` it runs the shell
/// dialogue (Dwm1001Shell) on every (re)connect and stops the stream on shutdown. The I/O
/// thread decodes and queues; a DeliveryQueue thread publishes, so a burst is never lost
/// silently: what does not fit is counted as dropped in the diagnostics.
class Dwm1001DriverNode {
 public:
  struct Params {
    std::string port;  ///< device path (udev symlink), required
    int baud = 115200;
    bool configure = true;            ///< run the shell dialogue; false = only listen
    std::string output_mode = "lec";  ///< "lec" or "les"
    std::string tag_id;               ///< used when configure is false ("" = unknown)
    std::string frame_id;             ///< "" = "uwb_<tag id>"
    std::string network_frame_id = "uwb_network";
    double reconnect_backoff = 1.0;  ///< s, longest wait between open attempts
    double silence_timeout = 2.0;    ///< s
    double shell_timeout = 2.0;      ///< s per dialogue step before it restarts
    int max_line_length = 1024;      ///< bytes

    void load(const ParamReader& private_nh);
    void validate() const;
  };

  Dwm1001DriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  ~Dwm1001DriverNode();

 private:
  void onBytes(const char* data, std::size_t size);
  void onConnected();
  void onDisconnected(const std::string& reason);
  /// The messages of one output line: built on the I/O thread, published on the queue's.
  struct Outgoing {
    bool has_ranges = false;
    UwbRanges ranges;
    bool has_location = false;
    UwbTagLocation location;
  };

  void onLine(std::string_view line, double stamp);
  void enqueue(double stamp);
  void publish(Outgoing& out);
  void onShellTimer(const ros::TimerEvent& event);
  std::string frameId() const;

  Params params_;
  ros::Publisher ranges_pub_;
  ros::Publisher location_pub_;
  drivers::DriverStats stats_;
  std::mutex mutex_;  // guards framer_, shell_, measurement_ (I/O thread vs timer)
  drivers::LineFramer framer_;
  drivers::Dwm1001Shell shell_;
  drivers::DwmMeasurement measurement_;
  std::unique_ptr<DriverDiagnostics> diagnostics_;
  std::optional<OutputDiagnostic> ranges_diagnostic_;  // ticked by the queue's thread
  std::optional<OutputDiagnostic> location_diagnostic_;
  ros::Timer shell_timer_;
  std::unique_ptr<drivers::DeliveryQueue<Outgoing>> queue_;
  std::unique_ptr<drivers::SerialTransport> transport_;
};

}  // namespace radio_follow
