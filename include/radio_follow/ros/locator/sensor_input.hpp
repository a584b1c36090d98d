// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <ros/ros.h>

#include <boost/function.hpp>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"

namespace radio_follow {

class LocatorInputs;

/// One measurement kind's ROS input to the Locator, after fuse's sensor models: it
/// subscribes to its driver's message, turns each message into its kind's readings
/// (estimation::Locator::add) and reports on what it heard. One class per kind, listed
/// once in sensor_inputs.cpp; the locator node and the replay name no kind.
class SensorInput {
 public:
  /// How the node runs the handling of one message (its callback barrier, its input
  /// watch): `handle` returns how many of the message's readings the locator refused.
  using Guard = std::function<void(const std::function<std::size_t()>& handle)>;

  explicit SensorInput(LocatorInputs& inputs) : inputs_(inputs) {}
  virtual ~SensorInput() = default;
  SensorInput(const SensorInput&) = delete;
  SensorInput& operator=(const SensorInput&) = delete;

  /// The node's private parameter listing its topics: its reading's kTopicsParam.
  virtual std::string topicsParam() const = 0;
  /// Its topics when every topics parameter is empty: the layout's convention.
  virtual std::vector<std::string> defaultTopics(const Layout& layout) const = 0;
  /// Subscribes to `topic`, each message handled inside `guard`.
  virtual ros::Subscriber subscribe(ros::NodeHandle& nh, const std::string& topic, Guard guard) = 0;
  /// Its lines of the locator's diagnostics.
  virtual void diagnose(diagnostic_updater::DiagnosticStatusWrapper& /*status*/) const {}

 protected:
  LocatorInputs& inputs_;
};

/// A SensorInput of one message type.
template <typename Message>
class MessageInput : public SensorInput {
 public:
  using SensorInput::SensorInput;

  /// Hands the message's readings to the locator; how many it refused.
  virtual std::size_t add(const Message& msg) = 0;
  /// The node's warnings after a message of which `refused` readings were refused.
  virtual void warn(const Message& /*msg*/, std::size_t /*refused*/) const {}

  ros::Subscriber subscribe(ros::NodeHandle& nh, const std::string& topic, Guard guard) override {
    const boost::function<void(const typename Message::ConstPtr&)> handler =
        [this, guard](const typename Message::ConstPtr& msg) {
          guard([&] {
            const std::size_t refused = add(*msg);
            warn(*msg, refused);
            return refused;
          });
        };
    return nh.subscribe<Message>(topic, 50, handler);
  }
};

/// Every kind's input (sensor_inputs.cpp: one line per kind).
std::vector<std::unique_ptr<SensorInput>> makeSensorInputs(LocatorInputs& inputs);

}  // namespace radio_follow
