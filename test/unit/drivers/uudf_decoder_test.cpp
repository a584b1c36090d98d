// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/uudf_decoder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/drivers/line_framer.hpp"

namespace radio_follow::drivers {
namespace {

// Thesis Appendix A (10 fields, the user string is a quoted comma) and the format
// comment of the reference driver brozb/xplraoa_ros (9 fields, reserved 0).
const std::string kThesis = "+UUDF:CCF9578E0D8A,-42,20,0,-43,37,\"CCF9578E0D89\",\",\",15869,23";
const std::string kNineFields = "+UUDF:6C1DEBA5F60C,-53,8,2,0,37,\"6C1DEBA09862\",\"\",1437347";

TEST(UudfDecoder, ThesisLine) {
  UudfEvent e;
  ASSERT_EQ(decodeUudfLine(kThesis, e), UudfLineStatus::kEvent);
  EXPECT_EQ(e.tag_id, "CCF9578E0D8A");
  EXPECT_EQ(e.anchor_id, "CCF9578E0D89");
  EXPECT_EQ(e.user_string, ",");
  EXPECT_DOUBLE_EQ(e.rssi, -42.0);
  EXPECT_DOUBLE_EQ(e.azimuth, deg2rad(20.0));
  EXPECT_DOUBLE_EQ(e.elevation, 0.0);
  EXPECT_DOUBLE_EQ(e.rssi_second, -43.0);
  EXPECT_EQ(e.channel, 37);
  EXPECT_EQ(e.timestamp_ms, 15869u);
  EXPECT_EQ(e.event_counter, 23);
}

TEST(UudfDecoder, NineFieldsWithReservedField) {
  UudfEvent e;
  ASSERT_EQ(decodeUudfLine(kNineFields, e), UudfLineStatus::kEvent);
  EXPECT_EQ(e.tag_id, "6C1DEBA5F60C");
  EXPECT_DOUBLE_EQ(e.azimuth, deg2rad(8.0));
  EXPECT_DOUBLE_EQ(e.elevation, deg2rad(2.0));
  EXPECT_TRUE(std::isnan(e.rssi_second));
  EXPECT_EQ(e.user_string, "");
  EXPECT_EQ(e.timestamp_ms, 1437347u);
  EXPECT_EQ(e.event_counter, -1);
}

TEST(UudfDecoder, NegativeAnglesEmptyAnchorAndCommasInUserString) {
  UudfEvent e;
  ASSERT_EQ(decodeUudfLine("+UUDF:ccf9578e0d8a,-70,-45,-12,-71,39,\"\",\"a,b,,c\",4294967295,0", e),
            UudfLineStatus::kEvent);
  EXPECT_EQ(e.tag_id, "CCF9578E0D8A");
  EXPECT_DOUBLE_EQ(e.azimuth, deg2rad(-45.0));
  EXPECT_DOUBLE_EQ(e.elevation, deg2rad(-12.0));
  EXPECT_EQ(e.anchor_id, "");
  EXPECT_EQ(e.user_string, "a,b,,c");
  EXPECT_EQ(e.channel, 39);
  EXPECT_EQ(e.timestamp_ms, 4294967295u);
  EXPECT_EQ(e.event_counter, 0);
}

TEST(UudfDecoder, IgnoresNonEvents) {
  UudfEvent e;
  for (const char* line : {"", "OK", "AT", "ATE0", "AT+UDFENABLE=1", "ERROR", "+STARTUP",
                           "+UUDFP:CCF9578E0D8A,\"0201060303AAFE\"", "  "}) {
    EXPECT_EQ(decodeUudfLine(line, e), UudfLineStatus::kIgnored) << line;
  }
}

TEST(UudfDecoder, RejectsBrokenEvents) {
  UudfEvent e;
  const std::vector<std::string> bad = {
      kThesis.substr(0, 30),                                            // cut
      kThesis.substr(0, kThesis.size() - 9),                            // cut after the user string
      kThesis + kThesis,                                                // merged
      kThesis + ",7",                                                   // 11 fields
      "+UUDF:CCF9578E0D8A,-42,20,0,-43,37,\"CCF9578E0D89\",\"\"",       // no timestamp
      "+UUDF:CCF9578E0D8,-42,20,0,-43,37,\"CCF9578E0D89\",\"\",15869",  // 11-digit tag
      "+UUDF:CCF9578E0D8A,-42,x,0,-43,37,\"CCF9578E0D89\",\"\",15869",  // bad azimuth
      "+UUDF:CCF9578E0D8A,-42,20,0,-43,40,\"A\",\"\",15869",            // channel 40
      "+UUDF:CCF9578E0D8A,-42,20,0,-43,37,CCF9578E0D89,\"\",15869",     // unquoted anchor
      "+UUDF:CCF9578E0D8A,-42,20,0,-43,37,\"CCF9578E0D89,\"\",15869",   // quote lost
      "+UUDF:CCF9578E0D8A,-42,20,0,-43,37,\"A\",\"\",15869,",           // empty counter
      "+UUDF:CCF9578E0D8A,-42,20,0,-43,37,\"A\",\"\",-5",               // negative time
      "+UUDF:",
      "+UUDF",
  };
  for (const std::string& line : bad) {
    EXPECT_EQ(decodeUudfLine(line, e), UudfLineStatus::kMalformed) << line;
  }
}

// The thesis line with one field replaced (0-based index after the prefix: 1 = RSSI,
// 2 = azimuth, 3 = elevation, 4 = second RSSI).
std::string thesisWith(std::size_t field, const std::string& value) {
  std::vector<std::string> fields = {"CCF9578E0D8A", "-42", "20", "0", "-43", "37"};
  fields[field] = value;
  std::string line = "+UUDF:";
  for (const std::string& f : fields) {
    line += f + ",";
  }
  return line + "\"CCF9578E0D89\",\",\",15869,23";
}

// Well-formed events carrying values the board cannot report are rejected as implausible,
// and the next good event still decodes.
TEST(UudfDecoder, RejectsImplausibleValuesAndRecovers) {
  const std::vector<std::pair<std::string, std::string>> implausible = {
      {thesisWith(1, "-128"), "RSSI below -127 dBm"},
      {thesisWith(1, "3"), "positive RSSI"},
      {thesisWith(1, "-1" + std::string(154, '0')), "RSSI -1e154 as plain digits"},
      {thesisWith(2, "91"), "azimuth 91 deg"},
      {thesisWith(2, "-90.5"), "azimuth -90.5 deg"},
      {thesisWith(2, "200"), "azimuth 200 deg"},
      {thesisWith(3, "95"), "elevation 95 deg"},
      {thesisWith(3, "-180"), "elevation -180 deg"},
  };
  UudfEvent e;
  for (const auto& [line, what] : implausible) {
    EXPECT_EQ(decodeUudfLine(line, e), UudfLineStatus::kImplausible) << what << ": " << line;
    ASSERT_EQ(decodeUudfLine(kThesis, e), UudfLineStatus::kEvent) << "after " << what;
    EXPECT_DOUBLE_EQ(e.azimuth, deg2rad(20.0));
    EXPECT_DOUBLE_EQ(e.rssi, -42.0);
  }
  EXPECT_STREQ(toString(UudfLineStatus::kImplausible), "implausible value");
}

// The fifth field (reserved on older firmware, the second polarisation's RSSI on newer)
// decides nothing but rssi_second: real boards send small positive values in it (issue 34:
// 6 was seen and the whole bearing was lost).
TEST(UudfDecoder, FifthFieldDecidesOnlyTheSecondRssi) {
  const std::vector<std::pair<std::string, std::string>> not_rssi = {
      {"6", "small positive value (seen on a real board)"},
      {"12", "positive value"},
      {"-300", "below -127 dBm"},
      {"-1" + std::string(154, '0'), "-1e154 as plain digits"},
      {"nan", "not a number"},
      {"x", "text"},
      {"", "empty"},
  };
  UudfEvent e;
  for (const auto& [value, what] : not_rssi) {
    ASSERT_EQ(decodeUudfLine(thesisWith(4, value), e), UudfLineStatus::kEvent) << what;
    EXPECT_TRUE(std::isnan(e.rssi_second)) << what;
    EXPECT_DOUBLE_EQ(e.azimuth, deg2rad(20.0)) << what;
    EXPECT_DOUBLE_EQ(e.rssi, -42.0) << what;
  }
  ASSERT_EQ(decodeUudfLine(thesisWith(4, "-61"), e), UudfLineStatus::kEvent);
  EXPECT_DOUBLE_EQ(e.rssi_second, -61.0);
}

TEST(UudfDecoder, AcceptsValuesAtThePlausibilityBounds) {
  UudfEvent e;
  ASSERT_EQ(decodeUudfLine("+UUDF:CCF9578E0D8A,-127,90,-90,0,37,\"A\",\"\",15869,23", e),
            UudfLineStatus::kEvent);
  EXPECT_DOUBLE_EQ(e.rssi, -127.0);
  EXPECT_DOUBLE_EQ(e.azimuth, deg2rad(90.0));
  EXPECT_DOUBLE_EQ(e.elevation, deg2rad(-90.0));
  EXPECT_TRUE(std::isnan(e.rssi_second));  // 0 is the reserved field, not a reading
  ASSERT_EQ(decodeUudfLine("+UUDF:CCF9578E0D8A,0,-90,90,-127,37,\"A\",\"\",15869,23", e),
            UudfLineStatus::kEvent);
  EXPECT_DOUBLE_EQ(e.rssi_second, -127.0);
}

// A cut or merged line stays malformed even if a surviving field is absurd.
TEST(UudfDecoder, StructureIsJudgedBeforeValues) {
  UudfEvent e;
  const std::string bad = thesisWith(2, "500");
  // Without its counter it is still a whole (nine-field) event: judged on its values.
  EXPECT_EQ(decodeUudfLine(bad.substr(0, bad.size() - 3), e), UudfLineStatus::kImplausible);
  EXPECT_EQ(decodeUudfLine(bad + ",7", e), UudfLineStatus::kMalformed);
  EXPECT_EQ(decodeUudfLine(bad.substr(0, 30), e), UudfLineStatus::kMalformed);
}

TEST(UudfDecoder, SplitAtEveryByteThroughFramer) {
  for (const std::string& line : {kThesis, kNineFields}) {
    const std::string wire = "OK\r\n" + line + "\r\n";
    for (std::size_t cut = 0; cut <= wire.size(); ++cut) {
      LineFramer framer;
      std::vector<std::string> lines;
      auto sink = [&](std::string_view l, double) { lines.emplace_back(l); };
      framer.feed(wire.data(), cut, 1.0, sink);
      framer.feed(wire.data() + cut, wire.size() - cut, 2.0, sink);
      ASSERT_EQ(lines.size(), 2u) << "cut " << cut;
      UudfEvent e;
      EXPECT_EQ(decodeUudfLine(lines[0], e), UudfLineStatus::kIgnored);
      EXPECT_EQ(decodeUudfLine(lines[1], e), UudfLineStatus::kEvent) << "cut " << cut;
      EXPECT_EQ(lines[1], line);
    }
  }
}

}  // namespace
}  // namespace radio_follow::drivers
