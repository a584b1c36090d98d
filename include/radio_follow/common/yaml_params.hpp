// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

#include "radio_follow/common/param_source.hpp"

namespace radio_follow {

/// A ParamSource read from a YAML mapping (a node's private parameter file), so tools
/// without a ROS master load a node's parameters with the node's own loading code, the
/// same keys and the same strictness: wrong types and non-finite numbers throw, and
/// requireAllKnown() refuses keys nobody read.
class YamlParams : public TypedParamSource<YamlParams> {
 public:
  explicit YamlParams(YAML::Node root) : root_(std::move(root)) {}
  /// Loads a file; throws ParamError naming the file when it is not a readable mapping.
  static YamlParams fromFile(const std::string& path);
  /// Loads several files into one namespace as `rosparam load` does one after the other:
  /// a later file's keys replace an earlier one's, mappings merge key by key.
  static YamlParams fromFiles(const std::vector<std::string>& paths);
  /// These parameters with `over`'s keys merged on top, as one more `rosparam load` (a
  /// mapping; an undefined or null node changes nothing).
  YamlParams mergedWith(const YAML::Node& over) const;

  void allow(const std::string& name) const override { known_.insert(name); }
  /// Throws ParamError for the first key (nested keys as "a/b") that no param() read.
  void requireAllKnown() const override;
  const YAML::Node& root() const { return root_; }

 private:
  friend class TypedParamSource<YamlParams>;
  template <typename T>
  bool readAs(const std::string& name, T& out) const;
  YAML::Node lookup(const std::string& name) const;

  YAML::Node root_;
  mutable std::set<std::string> known_;
};

}  // namespace radio_follow
