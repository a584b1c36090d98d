// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "radio_follow/common/throttle.hpp"
#include "radio_follow/drivers/delivery_queue.hpp"
#include "radio_follow/drivers/line_driver.hpp"
#include "radio_follow/drivers/serial_line_params.hpp"
#include "radio_follow/drivers/serial_transport.hpp"
#include "radio_follow/ros/common/callback_barrier.hpp"
#include "radio_follow/ros/common/output_diagnostic.hpp"
#include "radio_follow/ros/drivers/driver_diagnostics.hpp"

namespace radio_follow {

/// What the serial-line driver nodes (dwm1001_driver, ublox_aoa_driver) share: the port
/// on a drivers::SerialTransport, lines framed and counted by a drivers::LineDriver,
/// reconnects and rejected lines logged, the driver's diagnostics (DriverDiagnostics,
/// with its hardware id) and its output topics' diagnostics. A driver derives from
/// QueuedSerialLineDriver, which adds the delivery queue, and keeps only its decoder,
/// its device dialogue and its messages.
///
/// The hooks run on the transport's I/O thread with mutex() held; the text they return
/// is sent to the device. A derived constructor ends with start(), a derived destructor
/// begins with shutdown(): the I/O thread calls the hooks, so it must not run while the
/// derived part is being built or torn down.
class SerialLineDriver {
 public:
  virtual ~SerialLineDriver();
  SerialLineDriver(const SerialLineDriver&) = delete;
  SerialLineDriver& operator=(const SerialLineDriver&) = delete;

 protected:
  /// `name` names the diagnostics status (e.g. "dwm1001 /dev/dwm1001_5722").
  SerialLineDriver(ros::NodeHandle& nh, ros::NodeHandle& private_nh,
                   const drivers::SerialLineParams& params, const std::string& name,
                   const std::string& hardware_id);

  /// Watches an output topic ("<name> output <topic> topic status"): rate up to `max_hz`
  /// (the device's top rate) and at least one message per silence_timeout unless
  /// `rate_floor` is false; stamp age at most silence_timeout. Call tick() per message.
  OutputDiagnostic& watchOutput(const ros::Publisher& publisher, double max_hz,
                                bool rate_floor = true);

  /// Opens the port (on the transport's thread, retrying while it is absent).
  void start();
  /// Sends `farewell` if the port is open, then closes the port and joins its thread.
  void closePort(const std::string& farewell);
  /// Queues `text` for the device (dropped while the port is closed).
  void send(std::string text);

  /// The port (re)opened at `now`: returns the text that starts the device's dialogue.
  virtual std::string onOpened(double now);
  /// The port was lost.
  virtual void onClosed();
  /// One complete line, stamped with its first byte's receive time: decode it, count() it,
  /// queue what it carries; returns a reply for the device (or nothing).
  virtual std::string onLine(std::string_view line, double stamp) = 0;
  /// The bytes after the last line end once a chunk is framed (a prompt without newline).
  virtual std::string onPending(std::string_view pending, double now);
  /// Adds the driver's own key/values to its diagnostics status (diagnostics thread).
  virtual void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  /// Counts the verdict on `line` and warns (throttled) when it was rejected; `reason` is
  /// the decoder's name for its status.
  void count(drivers::LineVerdict verdict, std::string_view line, const char* reason);
  /// A measurement was pushed to the delivery queue (`kept` false: the queue was full).
  void queued(bool kept, std::size_t peak);
  /// A measurement was published (delivery thread).
  void published();
  /// Connected, and nothing received for longer than silence_timeout.
  bool silent(double now) const;

  /// The I/O thread's, the delivery thread's and the node's timers' callbacks run inside
  /// it: an exception is logged and counted, the stream goes on.
  CallbackBarrier barrier_;

  /// Guards the line state: the framer and whatever the hooks keep.
  std::mutex& mutex() { return mutex_; }
  const std::string& port() const { return options_.port; }

 private:
  void onConnected();
  void onDisconnected(const std::string& reason);
  void onBytes(const char* data, std::size_t size);

  drivers::SerialTransport::Options options_;
  double silence_timeout_;
  std::string name_;
  std::mutex mutex_;
  drivers::LineDriver line_;
  DriverDiagnostics diagnostics_;
  std::vector<std::unique_ptr<OutputDiagnostic>> outputs_;
  std::string first_topic_;     // of the first watched output, for the wiring log
  Throttle rejected_log_{5.0};  // I/O thread
  std::unique_ptr<drivers::SerialTransport> transport_;
};

/// A SerialLineDriver whose lines become `Item`s (the messages of one line), handed from
/// the I/O thread to a drivers::DeliveryQueue whose own thread publishes them: the port
/// is read on time while roscpp is busy, and what a burst overflows is counted as dropped.
template <typename Item>
class QueuedSerialLineDriver : public SerialLineDriver {
 protected:
  /// `queue_depth`: items the queue holds before it drops the oldest.
  QueuedSerialLineDriver(ros::NodeHandle& nh, ros::NodeHandle& private_nh,
                         const drivers::SerialLineParams& params, const std::string& name,
                         const std::string& hardware_id, std::size_t queue_depth)
      : SerialLineDriver(nh, private_nh, params, name, hardware_id),
        queue_(queue_depth, [this](Item& item) {
          barrier_.run("publish", [&] {
            publish(item);
            published();
          });
        }) {}

  /// Publishes one item (delivery thread).
  virtual void publish(Item& item) = 0;

  /// Hands `item` to the delivery thread (from onLine()).
  void enqueue(Item item) {
    const bool kept = queue_.push(std::move(item));
    queued(kept, queue_.peak());
  }

  /// Sends `farewell` if the port is open, closes it and publishes what is still queued.
  void shutdown(const std::string& farewell = {}) {
    closePort(farewell);
    queue_.stop();
  }

 private:
  drivers::DeliveryQueue<Item> queue_;
};

}  // namespace radio_follow
