// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>

namespace radio_follow {

/// requireKnownKeys() for a mapping of a configuration file (layout, scenario): throws
/// ParamError naming `path` + the first key not in `allowed` (a misspelt optional key,
/// e.g. `calibraton:`, would otherwise drop what it holds without a word), or `path` itself
/// when `map` is not a mapping. `path` is the mapping's place, e.g. "twr_modules[0].".
void requireYamlKeys(const YAML::Node& map, const std::set<std::string>& allowed,
                     const std::string& path);

}  // namespace radio_follow
