// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/yaml_keys.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"

namespace radio_follow {
namespace {

std::string flow(const YAML::Node& node) {
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

}  // namespace

std::string unreadablePathHint(const std::string& path) {
  std::error_code error;
  const std::filesystem::path file(path);
  if (std::filesystem::exists(file, error)) {
    return "; " + path + " exists but cannot be read (permissions?)";
  }
  if (!path.empty() && path[0] == '~') {
    return "; '~' is not expanded in a parameter: give the absolute path (/home/<user>/...)";
  }
  if (file.is_relative()) {
    return "; a relative path is read from the node's working directory " +
           std::filesystem::current_path(error).string() +
           " (roslaunch starts nodes in ROS_HOME): give an absolute path, e.g. "
           "$(find my_robot)/config/" +
           file.filename().string();
  }
  return "; there is no file " + path;
}

std::string readConfigFile(const std::string& path, const std::string& name,
                           const std::string& expected) {
  std::ifstream file(path);
  if (!file) {
    throw ParamError(name, paramValueString(path), expected + unreadablePathHint(path));
  }
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

YAML::Node loadConfigYaml(const std::string& text, const std::string& name,
                          const std::string& origin) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ParamError(name, paramValueString(origin), std::string("valid YAML (") + e.what() + ")");
  }
}

std::string yamlValueString(const YAML::Node& node) {
  return !node.IsDefined() || node.IsNull() ? "(missing)" : flow(node);
}

std::vector<double> yamlNumbers(const YAML::Node& node, const std::string& name,
                                const std::string& expected) {
  // A missing key of a const node is an invalid ("zombie") node: test IsDefined first.
  if (!node.IsDefined() || !node.IsSequence()) {
    throw ParamError(name, yamlValueString(node), expected);
  }
  std::vector<double> values;
  for (const auto& item : node) {
    try {
      values.push_back(item.as<double>());
    } catch (const YAML::Exception&) {
      throw ParamError(name, yamlValueString(node), expected);
    }
    if (!std::isfinite(values.back())) {
      throw ParamError(name, yamlValueString(node), expected);
    }
  }
  return values;
}

void requireYamlKeys(const YAML::Node& map, const std::set<std::string>& allowed,
                     const std::string& path) {
  if (!map.IsMap()) {
    throw ParamError(path.empty() ? "file" : path.substr(0, path.size() - 1),
                     map.IsDefined() ? flow(map) : "(missing)", "a mapping");
  }
  std::vector<PresentKey> present;
  for (const auto& kv : map) {
    present.push_back({kv.first.as<std::string>(), flow(kv.second)});
  }
  requireKnownKeys(present, allowed, {}, path);
}

}  // namespace radio_follow
