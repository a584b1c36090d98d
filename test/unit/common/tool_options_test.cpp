// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/tool_options.hpp"

#include <gtest/gtest.h>

#include <string>

#include "radio_follow/common/param_error.hpp"

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

TEST(ToolOptions, CountsAreWholeNumbersOrAnErrorNamingTheOption) {
  EXPECT_EQ(toolCount("--trials", "10000"), 10000u);
  EXPECT_EQ(toolCount("--first", "0"), 0u);
  EXPECT_EQ(toolCount("--sectors", "36", 1, 36), 36u);
  EXPECT_THROW(toolCount("--sectors", "37", 1, 36), ParamError);
  EXPECT_THROW(toolCount("--runs", "2147483648"), ParamError);  // past an int
  for (const char* bad : {"12x", "-1", "1e3", "", " 3", "0x10", "99999999999999999999"}) {
    EXPECT_THROW(toolCount("--trials", bad), ParamError) << bad;
  }
  try {
    toolCount("--trials", "0", 1);
    FAIL() << "0 accepted where at least 1 is expected";
  } catch (const ParamError& e) {
    EXPECT_NE(std::string(e.what()).find("--trials"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("[1, "), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace radio_follow
