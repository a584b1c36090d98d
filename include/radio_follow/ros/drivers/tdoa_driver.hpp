// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "radio_follow/TdoaMeasurements.h"
#include "radio_follow/common/param_table.hpp"
#include "radio_follow/drivers/delivery_queue.hpp"
#include "radio_follow/drivers/tdoa_receiver.hpp"
#include "radio_follow/drivers/tdoa_udp_transport.hpp"
#include "radio_follow/ros/common/callback_barrier.hpp"
#include "radio_follow/ros/common/output_diagnostic.hpp"
#include "radio_follow/ros/common/params.hpp"

namespace radio_follow {

/// ROS wrapper of the UDP TDoA driver: receives anchor reports (doc/tdoa_protocol.md),
/// groups them per blink and publishes `measurements` (TdoaMeasurements) with the
/// distance differences against the reference anchor. Messages go through a DeliveryQueue
/// whose thread publishes, so a burst is never lost silently: what does not fit is counted
/// in the diagnostics. See doc/nodes/tdoa_driver.md.
class TdoaDriverNode {
 public:
  struct Params {
    std::string address = "0.0.0.0";  ///< Local address to bind.
    int port = 6666;
    std::string frame_id = "base_link";  ///< Frame of the anchor positions.
    std::vector<drivers::TdoaAnchorConfig> anchors;
    std::string master;          ///< Anchor ID of the clock master (required).
    std::string reference;       ///< Anchor ID differences are taken against; empty = master.
    double group_window = 0.05;  ///< s
    double distance_variance = 0.0225;  ///< m^2
    double plausibility_margin = 0.5;   ///< m
    int min_anchors = 2;
    double data_timeout = 2.0;     ///< s without datagrams before a warning
    double initial_backoff = 0.5;  ///< s
    double max_backoff = 10.0;     ///< s

    /// Every parameter but the list ~anchors (config/tdoa_driver.yaml).
    static const ParamTable<Params>& table();
    /// Reads every parameter from `private_nh`; throws ParamError on a malformed value.
    void load(const ParamReader& private_nh);
    /// Throws ParamError naming the first invalid value.
    void validate() const;
    /// The core configuration (anchor IDs resolved to indices). Call after validate().
    drivers::TdoaDifferenceConfig differenceConfig() const;
  };

  TdoaDriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh);
  ~TdoaDriverNode();

 private:
  void onDatagram(const std::uint8_t* data, std::size_t size);
  void onSocketError(const std::string& what, double retry_in);
  void onTimer(const ros::TimerEvent& event);
  void publish(const std::vector<drivers::TdoaBlink>& blinks);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  Params params_;
  CallbackBarrier barrier_;  // the I/O, delivery and timer callbacks run inside it
  std::mutex mutex_;         // guards receiver_, blinks_, last_datagram_, rate counters
  std::unique_ptr<drivers::TdoaReceiver> receiver_;
  std::vector<drivers::TdoaBlink> blinks_;
  ros::WallTime last_datagram_;
  ros::WallTime last_diagnosis_;
  std::uint64_t packets_at_last_diagnosis_ = 0;
  std::uint64_t blinks_at_last_diagnosis_ = 0;
  std::uint64_t last_logged_rejections_ = 0;
  std::uint64_t blinks_unpublished_ = 0;  // queue full
  std::uint64_t unpublished_at_last_diagnosis_ = 0;
  std::atomic<std::uint64_t> blinks_published_{0};  // written by the queue's thread
  ros::Publisher pub_;
  std::unique_ptr<drivers::DeliveryQueue<TdoaMeasurements>> queue_;
  ros::Timer timer_;
  diagnostic_updater::Updater diagnostics_;
  std::optional<OutputDiagnostic> output_diagnostic_;  // ticked by the queue's thread
  std::unique_ptr<drivers::TdoaUdpTransport> transport_;
};

}  // namespace radio_follow
