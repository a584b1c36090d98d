// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <utility>

namespace radio_follow {

/// The exception barrier of a node (issue 34, doc/time.md "Nothing a node receives can
/// crash it"): no callback lets an exception escape into roscpp, which would abort the
/// process (exit 134) and leave the robot on its last command. A callback that throws is
/// cut short; the exception is logged (throttled, naming the callback) and counted, the
/// node's fault action runs (a controller stops the robot for hold_time), and the node
/// goes on with the next message.
///
/// Every subscriber, timer and wall timer of a node is made through one barrier (or runs
/// its body through run()). Services need none: roscpp turns their exceptions into a
/// failed call.
class CallbackBarrier {
 public:
  /// `where` is the callback (a topic or timer name), `what` the exception's text.
  using FaultAction = std::function<void(const std::string& where, const std::string& what)>;

  CallbackBarrier() = default;
  CallbackBarrier(const CallbackBarrier&) = delete;
  CallbackBarrier& operator=(const CallbackBarrier&) = delete;

  /// What the node does after a callback threw (called inside the barrier: an exception
  /// from the action itself is logged and dropped).
  void setFaultAction(FaultAction action) { action_ = std::move(action); }

  /// Runs `body`; never throws.
  template <typename Body>
  void run(const std::string& where, Body&& body) noexcept {
    try {
      body();
    } catch (const std::exception& e) {
      fault(where, e.what());
    } catch (...) {
      fault(where, "an exception of unknown type");
    }
  }

  /// A subscriber whose callback is `object->method(msg)` inside the barrier.
  template <typename Message, typename Object>
  ros::Subscriber subscribe(ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue,
                            void (Object::*method)(const boost::shared_ptr<Message const>&),
                            Object* object,
                            const ros::TransportHints& hints = ros::TransportHints()) {
    const std::string where = nh.resolveName(topic);
    const boost::function<void(const boost::shared_ptr<Message const>&)> callback =
        [this, where, method, object](const boost::shared_ptr<Message const>& msg) {
          run(where, [&] { (object->*method)(msg); });
        };
    return nh.subscribe<Message>(topic, queue, callback, ros::VoidConstPtr(), hints);
  }

  /// A subscriber whose callback (any callable taking the message) runs inside the barrier.
  template <typename Message>
  ros::Subscriber subscribe(ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue,
                            std::function<void(const boost::shared_ptr<Message const>&)> body) {
    const std::string where = nh.resolveName(topic);
    const boost::function<void(const boost::shared_ptr<Message const>&)> callback =
        [this, where, body = std::move(body)](const boost::shared_ptr<Message const>& msg) {
          run(where, [&] { body(msg); });
        };
    return nh.subscribe<Message>(topic, queue, callback);
  }

  /// A timer whose callback (any callable taking the event) runs inside the barrier.
  ros::Timer timer(ros::NodeHandle& nh, const ros::Duration& period, const std::string& name,
                   std::function<void(const ros::TimerEvent&)> body, bool oneshot = false) {
    return nh.createTimer(
        period,
        [this, name, body = std::move(body)](const ros::TimerEvent& event) {
          run(name, [&] { body(event); });
        },
        oneshot);
  }

  /// A timer whose callback runs inside the barrier; `name` says which in the log.
  template <typename Object>
  ros::Timer timer(ros::NodeHandle& nh, const ros::Duration& period, const std::string& name,
                   void (Object::*method)(const ros::TimerEvent&), Object* object,
                   bool oneshot = false) {
    return nh.createTimer(
        period,
        [this, name, method, object](const ros::TimerEvent& event) {
          run(name, [&] { (object->*method)(event); });
        },
        oneshot);
  }

  /// A wall timer whose callback runs inside the barrier.
  ros::WallTimer wallTimer(ros::NodeHandle& nh, const ros::WallDuration& period,
                           const std::string& name,
                           std::function<void(const ros::WallTimerEvent&)> callback,
                           bool oneshot = false) {
    return nh.createWallTimer(
        period,
        [this, name, callback = std::move(callback)](const ros::WallTimerEvent& event) {
          run(name, [&] { callback(event); });
        },
        oneshot);
  }

  /// Exceptions stopped so far.
  std::uint64_t faults() const { return faults_; }
  /// The newest one, "<callback>: <text>"; empty before the first.
  std::string lastFault() const;

 private:
  void fault(const std::string& where, const char* what) noexcept;

  FaultAction action_;
  std::atomic<std::uint64_t> faults_{0};
  mutable std::mutex last_mutex_;
  std::string last_;
};

}  // namespace radio_follow
