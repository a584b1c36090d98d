// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <set>
#include <string>
#include <vector>

#include "radio_follow/common/param_source.hpp"

namespace radio_follow {

/// The one way a node reads its private parameters (doc/configuration.md, "Strict
/// parameters"): a ParamSource on the ROS parameter server. Unlike
/// ros::NodeHandle::param, which silently keeps the default when a value has the wrong
/// type, every read is strict:
/// - a value of the wrong type (`_safe_distance:=abc`, a string where a list is expected)
///   or a non-finite number throws ParamError naming the parameter, value and type;
/// - an int is accepted where a double is expected (`_safe_distance:=2`), nothing else;
/// - every name read is remembered, so that requireAllKnown() can refuse the keys nobody
///   read (`_safe_distanse:=2.0`, a file meant for another node).
/// The same loading code runs on a YamlParams (tools without a master).
class ParamReader : public TypedParamSource<ParamReader> {
 public:
  /// `shown_as` prefixes a parameter's name in messages: "~" for the node's private
  /// namespace, "~dwm1001/" for a reader on a sub-namespace of it.
  explicit ParamReader(const ros::NodeHandle& private_nh, std::string shown_as = "~");

  /// Raw access for structured values (lists of mappings); marks `name` as known.
  /// Returns false when the parameter is not set.
  bool getRaw(const std::string& name, XmlRpc::XmlRpcValue& out) const;
  /// Keys below `ns` belong to another component (a dynamic_reconfigure server's
  /// namespace, which it rewrites itself) and are never reported as unknown.
  void own(const std::string& ns) const;
  void allow(const std::string& name) const override;
  /// Throws ParamError for the first parameter in the private namespace that no load
  /// function read: call it once every parameter struct of the node has been loaded,
  /// before any subscriber exists.
  void requireAllKnown() const override;

  const ros::NodeHandle& handle() const { return nh_; }

 private:
  friend class TypedParamSource<ParamReader>;
  template <typename T>
  bool readAs(const std::string& name, T& out) const;
  std::string relative(const std::string& resolved) const;

  ros::NodeHandle nh_;
  mutable std::set<std::string> known_;
  mutable std::vector<std::string> owned_;
  std::string shown_as_;
};

/// Throws ParamError for a member of the mapping `item` (an element of a structured list
/// parameter, e.g. "~unplug[0]") that is not in `allowed`: a misspelt optional field
/// would otherwise fall back to its default unnoticed.
void requireMembers(const XmlRpc::XmlRpcValue& item, const std::set<std::string>& allowed,
                    const std::string& path);

/// Throws ParamError unless `name` is a valid ROS graph resource name (a topic or frame
/// that roscpp would otherwise abort on at advertise/subscribe time).
void requireGraphName(const std::string& param, const std::string& name);

/// A node's parameter struct loaded through `params` and validated (throws ParamError
/// naming the first bad parameter), for a constructor's initialiser list.
template <typename Params>
Params loadValidated(const ParamReader& params) {
  Params p;
  p.load(params);
  p.validate();
  return p;
}

/// The whole parameter step of a simple node: `Params` loaded from the private
/// namespace, no unknown key left (ParamReader::requireAllKnown), validated.
template <typename Params>
Params loadStrict(const ros::NodeHandle& private_nh) {
  const ParamReader params(private_nh);
  Params p;
  p.load(params);
  params.requireAllKnown();
  p.validate();
  return p;
}

/// Marks the fields of a dynamic_reconfigure config `Tuning` as known: its server writes
/// them into the node's namespace, where a restarted node finds them.
template <typename Tuning>
void allowTuning(const ParamReader& params) {
  for (const auto& description : Tuning::__getParamDescriptions__()) {
    params.allow(description->name);
  }
}

}  // namespace radio_follow
