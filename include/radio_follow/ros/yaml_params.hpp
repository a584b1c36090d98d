// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {

/// A parameter source with ros::NodeHandle::param()'s shape, read from a YAML mapping
/// (a node's private parameter file), so tools without a ROS master load a node's
/// parameters with the node's own loading code and the same keys.
class YamlParams {
 public:
  explicit YamlParams(YAML::Node root) : root_(std::move(root)) {}
  /// Loads a file; throws ParamError naming the file when it is not a readable mapping.
  static YamlParams fromFile(const std::string& path);

  /// `out` = the value under `name`, or `fallback` when absent; a value of the wrong type
  /// throws ParamError naming the parameter.
  template <typename T>
  void param(const std::string& name, T& out, const T& fallback) const {
    const YAML::Node value = root_[name];
    if (!value.IsDefined() || value.IsNull()) {
      out = fallback;
      return;
    }
    try {
      out = value.as<T>();
    } catch (const YAML::Exception&) {
      throw ParamError("~" + name, YAML::Dump(value), "a value of the parameter's type");
    }
  }

  const YAML::Node& root() const { return root_; }

 private:
  YAML::Node root_;
};

}  // namespace radio_follow
