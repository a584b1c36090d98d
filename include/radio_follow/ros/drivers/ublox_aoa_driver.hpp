// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "radio_follow/AoaBearing.h"
#include "radio_follow/drivers/delivery_queue.hpp"
#include "radio_follow/drivers/driver_stats.hpp"
#include "radio_follow/drivers/line_framer.hpp"
#include "radio_follow/drivers/serial_transport.hpp"
#include "radio_follow/drivers/uudf_decoder.hpp"
#include "radio_follow/ros/drivers/driver_diagnostics.hpp"
#include "radio_follow/ros/common/output_diagnostic.hpp"
#include "radio_follow/ros/common/params.hpp"

namespace radio_follow {

/// Driver for a u-blox XPLR-AOA-1 / ANT-B10 antenna board running u-connectLocate.
/// Publishes `bearing` (AoaBearing) for every +UUDF event of an accepted tag. The I/O
/// thread decodes and queues; a DeliveryQueue thread publishes, so a burst is never lost
/// silently: what does not fit is counted as dropped in the diagnostics.
class UbloxAoaDriverNode {
 public:
  struct Params {
    std::string port;  ///< device path (udev symlink), required
    int baud = 115200;
    std::string frame_id;                    ///< the board's frame, required
    std::vector<std::string> tag_ids;        ///< accepted tags (12 hex digits); empty = all
    bool invert_azimuth = true;              ///< publish counter-clockwise azimuth
    std::vector<std::string> init_commands;  ///< AT commands sent on every connect
    double reconnect_backoff = 1.0;          ///< s, longest wait between open attempts
    double silence_timeout = 2.0;            ///< s
    int max_line_length = 1024;              ///< bytes

    void load(const ParamReader& private_nh);
    void validate() const;
  };

  UbloxAoaDriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  ~UbloxAoaDriverNode();

 private:
  void onBytes(const char* data, std::size_t size);
  void onConnected();
  void onLine(std::string_view line, double stamp);
  bool accepted(const std::string& tag_id) const;

  Params params_;
  ros::Publisher bearing_pub_;
  drivers::DriverStats stats_;
  std::mutex mutex_;  // guards framer_ and event_
  drivers::LineFramer framer_;
  drivers::UudfEvent event_;
  std::unique_ptr<DriverDiagnostics> diagnostics_;
  std::optional<OutputDiagnostic> bearing_diagnostic_;  // ticked by the queue's thread
  std::unique_ptr<drivers::DeliveryQueue<AoaBearing>> queue_;
  std::unique_ptr<drivers::SerialTransport> transport_;
};

}  // namespace radio_follow
