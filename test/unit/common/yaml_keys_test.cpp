// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/yaml_keys.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace {

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const ParamError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ConfigFiles, ReadAndParseOrNameTheFileAndTheProblem) {
  const std::string path = std::filesystem::temp_directory_path() / "yaml_keys_test.yaml";
  std::ofstream(path) << "a: [1, 2]\n";
  EXPECT_EQ(readConfigFile(path, "layout", "a readable file"), "a: [1, 2]\n");
  EXPECT_EQ(messageOf([] { readConfigFile("/nonexistent.yaml", "points", "a readable file"); }),
            "parameter 'points' = '/nonexistent.yaml': expected a readable file; there is no "
            "file /nonexistent.yaml");
  // Where a node looks for a relative path, and that `~` is not the home directory.
  EXPECT_NE(messageOf([] {
              readConfigFile("robot.yaml", "layout", "a readable file");
            }).find("a relative path is read from the node's working directory"),
            std::string::npos);
  EXPECT_NE(messageOf([] {
              readConfigFile("~/robot.yaml", "layout", "a readable file");
            }).find("'~' is not expanded"),
            std::string::npos);
  EXPECT_EQ(loadConfigYaml("a: [1, 2]\n", "layout", path)["a"].size(), 2u);
  EXPECT_NE(messageOf([] {
              loadConfigYaml("a: [1, 2\n", "layout", "x.yaml");
            }).find("parameter 'layout' = 'x.yaml': expected valid YAML ("),
            std::string::npos);
}

TEST(YamlValueString, FlowStyleOrMissing) {
  const YAML::Node root = YAML::Load("a: [1, 2]\nb: {c: x}\nn: ~\n");
  EXPECT_EQ(yamlValueString(root["a"]), "[1, 2]");
  EXPECT_EQ(yamlValueString(root["b"]), "{c: x}");
  EXPECT_EQ(yamlValueString(root["n"]), "(missing)");
  EXPECT_EQ(yamlValueString(root["absent"]), "(missing)");
}

}  // namespace
}  // namespace radio_follow
