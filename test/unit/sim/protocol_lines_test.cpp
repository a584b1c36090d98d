// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/protocol_lines.hpp"

#include <gtest/gtest.h>

namespace radio_follow {
namespace sim {
namespace {

std::vector<DwmAnchorRange> appendixRanges() {
  return {{"1151", Eigen::Vector3d(5.0, 8.0, 2.25), 6.48},
          {"0CA8", Eigen::Vector3d(0.0, 8.0, 2.25), 6.51}};
}

TEST(ProtocolLines, LesLineAsInTheThesisAppendix) {
  DwmPosition position{Eigen::Vector3d(2.57, 1.98, 1.68), 100, 2576};
  EXPECT_EQ(formatLesLine(appendixRanges(), position),
            "1151[5.00,8.00,2.25]=6.48 0CA8[0.00,8.00,2.25]=6.51 le_us=2576 "
            "est[2.57,1.98,1.68,100]");
  EXPECT_EQ(formatLesLine({{"DA12", Eigen::Vector3d(-1.5, 0, 12.25), 10.0}}, std::nullopt),
            "DA12[-1.50,0.00,12.25]=10.00");
}

TEST(ProtocolLines, LecLineCountsItsAnchors) {
  DwmPosition position{Eigen::Vector3d(2.57, 1.98, 1.68), 100, 0};
  EXPECT_EQ(formatLecLine(appendixRanges(), position),
            "DIST,2,AN0,1151,5.00,8.00,2.25,6.48,AN1,0CA8,0.00,8.00,2.25,6.51,"
            "POS,2.57,1.98,1.68,100");
  EXPECT_EQ(formatLecLine({}, std::nullopt), "DIST,0");
}

TEST(ProtocolLines, UudfLineAsInTheThesisAppendix) {
  UudfEvent e;
  e.tag_id = "CCF9578E0D8A";
  e.rssi = -42;
  e.azimuth = 20;
  e.elevation = 0;
  e.rssi_second = -43;
  e.channel = 37;
  e.anchor_id = "CCF9578E0D89";
  e.user_defined = ",";
  e.timestamp_ms = 15869;
  e.event_counter = 23;
  EXPECT_EQ(formatUudfLine(e),
            "+UUDF:CCF9578E0D8A,-42,20,0,-43,37,\"CCF9578E0D89\",\",\",15869,23");
  e.event_counter.reset();
  e.user_defined.clear();
  EXPECT_EQ(formatUudfLine(e), "+UUDF:CCF9578E0D8A,-42,20,0,-43,37,\"CCF9578E0D89\",\"\",15869");
}

}  // namespace
}  // namespace sim
}  // namespace radio_follow
