// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {

/// A parameter source with ParamReader's shape, read from a YAML mapping (a node's
/// private parameter file), so tools without a ROS master load a node's parameters
/// with the node's own loading code, the same keys and the same strictness: wrong types
/// and non-finite numbers throw, and requireAllKnown() refuses keys nobody read.
class YamlParams {
 public:
  explicit YamlParams(YAML::Node root) : root_(std::move(root)) {}
  /// Loads a file; throws ParamError naming the file when it is not a readable mapping.
  static YamlParams fromFile(const std::string& path);

  /// `out` = the value under `name` ("a/b" reads a nested mapping), or `fallback` when
  /// absent; a value of the wrong type throws ParamError naming the parameter.
  template <typename T>
  void param(const std::string& name, T& out, const T& fallback) const {
    known_.insert(name);
    const YAML::Node value = lookup(name);
    if (!value.IsDefined() || value.IsNull()) {
      out = fallback;
      return;
    }
    try {
      out = value.as<T>();
    } catch (const YAML::Exception&) {
      throw ParamError("~" + name, YAML::Dump(value), "a value of the parameter's type");
    }
    if constexpr (std::is_floating_point_v<T>) {
      require(std::isfinite(out), "~" + name, out, "a finite number");
    }
  }

  /// Throws ParamError for the first key (nested keys as "a/b") that no param() read.
  void requireAllKnown() const;

  const YAML::Node& root() const { return root_; }

 private:
  YAML::Node lookup(const std::string& name) const;

  YAML::Node root_;
  mutable std::set<std::string> known_;
};

}  // namespace radio_follow
