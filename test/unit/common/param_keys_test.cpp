// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/param_keys.hpp"

#include <gtest/gtest.h>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace {

const std::set<std::string> kKnown{"safe_distance", "estimate_timeout", "range_timeout",
                                   "linear_pid/kp"};

TEST(ParamKeys, NearestKeyFindsTyposOnly) {
  EXPECT_EQ(nearestKey("safe_distanse", kKnown), "safe_distance");
  EXPECT_EQ(nearestKey("linear_pid/kq", kKnown), "linear_pid/kp");
  EXPECT_EQ(nearestKey("colour", kKnown), "");  // nothing plausible
}

TEST(ParamKeys, UnknownKeyIsRefusedWithItsValueAndASuggestion) {
  try {
    requireKnownKeys({{"safe_distance", "1.3"}, {"safe_distanse", "2.0"}}, kKnown, {}, "~");
    FAIL() << "a misspelt key was accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~safe_distanse");
    EXPECT_NE(std::string(e.what()).find("= 2.0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("did you mean '~safe_distance'"), std::string::npos)
        << e.what();
  }
}

TEST(ParamKeys, KnownAndOwnedKeysPass) {
  EXPECT_NO_THROW(requireKnownKeys({{"safe_distance", "1"}, {"law/follow_distance", "1.6"}}, kKnown,
                                   {"law"}, "~"));
  // "law" owns keys below it, not a key that merely starts with the same letters.
  EXPECT_THROW(requireKnownKeys({{"lawful", "1"}}, kKnown, {"law"}, "~"), ParamError);
}

TEST(ParamKeys, IdsAreNormalisedToUpperCaseWithoutBlanks) {
  EXPECT_EQ(normalizeId("da12"), "DA12");
  EXPECT_EQ(normalizeId(" 5a84\t"), "5A84");
  EXPECT_EQ(normalizeId("ccf9578e0d8a"), "CCF9578E0D8A");
  EXPECT_EQ(normalizeId("  "), "");
}

}  // namespace
}  // namespace radio_follow
