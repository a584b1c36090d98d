// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <ros/ros.h>
#include <ros/serialization.h>

#include <boost/function.hpp>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"

namespace radio_follow {

class LocatorInputs;

/// Which of the layout's sensors the messages named, and the names the layout does not
/// have (a replay's check that the layout is the recorded robot's).
struct SensorMatch {
  std::set<std::string> heard;      ///< layout IDs
  std::set<std::string> strangers;  ///< e.g. "module 0C1F", "board frame aoa_x"
};

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
  /// A serialized message of its type (a bag's, the replay): as if it had arrived; how
  /// many of its readings the locator refused.
  virtual std::size_t addSerialized(const std::vector<std::uint8_t>& data) = 0;
  /// Its lines of the locator's diagnostics.
  virtual void diagnose(diagnostic_updater::DiagnosticStatusWrapper& /*status*/) const {}
  /// The sensors its messages named so far.
  virtual void match(SensorMatch& /*match*/) const {}

 protected:
  LocatorInputs& inputs_;
};

/// A message of type `Message` from its serialized bytes.
template <typename Message>
Message deserialized(const std::vector<std::uint8_t>& data) {
  Message msg;
  ros::serialization::IStream stream(const_cast<std::uint8_t*>(data.data()),
                                     static_cast<std::uint32_t>(data.size()));
  ros::serialization::deserialize(stream, msg);
  return msg;
}

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

  std::size_t addSerialized(const std::vector<std::uint8_t>& data) override {
    return add(deserialized<Message>(data));
  }
};

/// A kind's entry in the one list of inputs (sensor_inputs.cpp): its message type, what
/// a replay needs to read its messages from a bag, and how to make its input.
struct SensorInputKind {
  std::string message_type;  ///< e.g. "radio_follow/UwbRanges"
  std::string md5sum;        ///< of the message definition (a bag's may be older)
  /// The header stamp of a serialized message, s.
  double (*stamp)(const std::vector<std::uint8_t>& data);
  std::unique_ptr<SensorInput> (*make)(LocatorInputs& inputs);
};

template <typename Message>
SensorInputKind sensorInputKind(std::unique_ptr<SensorInput> (*make)(LocatorInputs&)) {
  return {ros::message_traits::datatype<Message>(), ros::message_traits::md5sum<Message>(),
          [](const std::vector<std::uint8_t>& data) {
            return deserialized<Message>(data).header.stamp.toSec();
          },
          make};
}

/// Every kind's input, in one list (sensor_inputs.cpp: one line per kind).
const std::vector<SensorInputKind>& sensorInputKinds();

}  // namespace radio_follow
