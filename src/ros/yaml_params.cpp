// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/yaml_params.hpp"

namespace radio_follow {

YamlParams YamlParams::fromFile(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ParamError("parameter file", "'" + path + "'",
                     std::string("a readable YAML file (") + e.what() + ")");
  }
  if (!root.IsMap() && !root.IsNull()) {
    throw ParamError("parameter file", "'" + path + "'", "a YAML mapping of parameters");
  }
  return YamlParams(root.IsNull() ? YAML::Node(YAML::NodeType::Map) : root);
}

}  // namespace radio_follow
