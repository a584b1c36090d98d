// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/tool_options.hpp"

#include <gtest/gtest.h>

namespace radio_follow {
namespace {

std::map<std::string, std::string> defaults() {
  return {{"--runs", "100"}, {"--layout", "spot"}};
}

TEST(ToolOptions, ReadsValuesAndKeepsDefaults) {
  const char* argv[] = {"tool", "--runs", "7"};
  auto options = defaults();
  EXPECT_FALSE(readToolOptions(3, argv, options));
  EXPECT_EQ(options["--runs"], "7");
  EXPECT_EQ(options["--layout"], "spot");
}

TEST(ToolOptions, NamesAnUnknownOptionOrAMissingValue) {
  const char* unknown[] = {"tool", "--layout", "cube", "--trials", "3"};
  auto options = defaults();
  EXPECT_EQ(readToolOptions(5, unknown, options), "unknown option or no value: --trials");
  const char* missing[] = {"tool", "--runs"};
  EXPECT_EQ(readToolOptions(2, missing, options), "unknown option or no value: --runs");
}

}  // namespace
}  // namespace radio_follow
