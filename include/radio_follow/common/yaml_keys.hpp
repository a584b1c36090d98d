// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {

/// requireKnownKeys() for a mapping of a configuration file (layout, scenario): throws
/// ParamError naming `path` + the first key not in `allowed` (a misspelt optional key,
/// e.g. `calibraton:`, would otherwise drop what it holds without a word), or `path` itself
/// when `map` is not a mapping. `path` is the mapping's place, e.g. "twr_modules[0].".
void requireYamlKeys(const YAML::Node& map, const std::set<std::string>& allowed,
                     const std::string& path);

/// What to do about a configuration file that cannot be read, as "; ..." to append to
/// the expectation: `~` is not expanded, a relative path is read from the node's working
/// directory (ROS_HOME under roslaunch), the file does not exist, or it is not readable.
std::string unreadablePathHint(const std::string& path);

/// The text of a configuration file; throws ParamError(`name`, path, `expected`) when it
/// cannot be read (e.g. "layout", "a readable layout YAML file").
std::string readConfigFile(const std::string& path, const std::string& name,
                           const std::string& expected);

/// The YAML document of a configuration file's text; throws ParamError(`name`, origin,
/// "valid YAML (...)") with the parser's message when it is not YAML.
YAML::Node loadConfigYaml(const std::string& text, const std::string& name,
                          const std::string& origin);

/// A YAML value as a ParamError message shows it: in flow style (`[1, 2]`, `{a: 1}`), or
/// "(missing)" for an absent or null node.
std::string yamlValueString(const YAML::Node& node);

/// The scalar `parent[key]` as a T. Throws ParamError(`path` + key, value, `expected`) when
/// it is of the wrong type, or when it is absent and no `fallback` is given.
template <typename T>
T yamlScalar(const YAML::Node& parent, const std::string& key, const std::string& path,
             const std::string& expected, const T* fallback = nullptr) {
  const YAML::Node node = parent[key];
  if (!node.IsDefined() || node.IsNull()) {
    if (fallback != nullptr) {
      return *fallback;
    }
    throw ParamError(path + key, "(missing)", expected);
  }
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    throw ParamError(path + key, yamlValueString(node), expected);
  }
}

/// The sequence `node` as finite numbers; throws ParamError(`name`, value, `expected`) when
/// it is absent, not a sequence, or holds anything else.
std::vector<double> yamlNumbers(const YAML::Node& node, const std::string& name,
                                const std::string& expected);

}  // namespace radio_follow
