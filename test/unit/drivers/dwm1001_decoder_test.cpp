// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/dwm1001_decoder.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "radio_follow/drivers/line_framer.hpp"

namespace radio_follow::drivers {
namespace {

// Thesis Appendix A (OCR artefacts "OCA8"/"1e_us" and stray spaces removed) and the
// DWM1001 Firmware API Guide's shell examples.
const std::string kLes =
    "1151[5.00,8.00,2.25]=6.48 0CA8[0.00,8.00,2.25]=6.51 111C[5.00,0.00,2.25]=3.18 "
    "1150[0.00,0.00,2.25]=3.16 le_us=2576 est[2.57,1.98,1.68,100]";
const std::string kLec =
    "DIST,4,AN0,1151,5.00,8.00,2.25,6.48,AN1,0CA8,0.00,8.00,2.25,6.51,AN2,111C,5.00,0.00,"
    "2.25,3.18,AN3,1150,0.00,0.00,2.25,3.16,POS,2.57,1.98,1.68,100";
const std::string kLep = "POS,2.57,1.98,1.68,100";

void expectThesisRanges(const DwmMeasurement& m) {
  ASSERT_EQ(m.ranges.size(), 4u);
  EXPECT_EQ(m.ranges[0].id, "1151");
  EXPECT_DOUBLE_EQ(m.ranges[0].x, 5.0);
  EXPECT_DOUBLE_EQ(m.ranges[0].y, 8.0);
  EXPECT_DOUBLE_EQ(m.ranges[0].z, 2.25);
  EXPECT_DOUBLE_EQ(m.ranges[0].range, 6.48);
  EXPECT_EQ(m.ranges[1].id, "0CA8");
  EXPECT_DOUBLE_EQ(m.ranges[1].range, 6.51);
  EXPECT_EQ(m.ranges[3].id, "1150");
  EXPECT_DOUBLE_EQ(m.ranges[3].range, 3.16);
  ASSERT_TRUE(m.has_position);
  EXPECT_DOUBLE_EQ(m.position.x, 2.57);
  EXPECT_DOUBLE_EQ(m.position.y, 1.98);
  EXPECT_DOUBLE_EQ(m.position.z, 1.68);
  EXPECT_EQ(m.position.quality, 100);
}

TEST(Dwm1001Decoder, LesThesisLine) {
  DwmMeasurement m;
  ASSERT_EQ(decodeDwmLine(kLes, m), DwmLineStatus::kMeasurement);
  expectThesisRanges(m);
  EXPECT_EQ(m.computation_time_us, 2576u);
}

TEST(Dwm1001Decoder, LecLine) {
  DwmMeasurement m;
  ASSERT_EQ(decodeDwmLine(kLec, m), DwmLineStatus::kMeasurement);
  expectThesisRanges(m);
  EXPECT_EQ(m.computation_time_us, 0u);
}

TEST(Dwm1001Decoder, LepLineHasOnlyPosition) {
  DwmMeasurement m;
  ASSERT_EQ(decodeDwmLine(kLep, m), DwmLineStatus::kMeasurement);
  EXPECT_TRUE(m.ranges.empty());
  ASSERT_TRUE(m.has_position);
  EXPECT_DOUBLE_EQ(m.position.z, 1.68);
}

TEST(Dwm1001Decoder, WithoutPositionPartAndFewAnchors) {
  DwmMeasurement m;
  ASSERT_EQ(decodeDwmLine("1151[5.00,8.00,2.25]=6.48 0ca8[0.00,8.00,2.25]=6.51", m),
            DwmLineStatus::kMeasurement);
  ASSERT_EQ(m.ranges.size(), 2u);
  EXPECT_EQ(m.ranges[1].id, "0CA8");  // normalised to upper case
  EXPECT_FALSE(m.has_position);
  ASSERT_EQ(decodeDwmLine("DIST,1,AN0,DA12,0.00,0.00,0.00,0.45", m), DwmLineStatus::kMeasurement);
  ASSERT_EQ(m.ranges.size(), 1u);
  EXPECT_FALSE(m.has_position);
  ASSERT_EQ(decodeDwmLine("DIST,0,POS,1.00,2.00,3.00,50", m), DwmLineStatus::kMeasurement);
  EXPECT_TRUE(m.ranges.empty());
  EXPECT_EQ(m.position.quality, 50);
}

TEST(Dwm1001Decoder, NegativeAndMultiDigitCoordinatesAndManyAnchors) {
  std::string line;
  for (int i = 0; i < 12; ++i) {
    line += "1" + std::to_string(100 + i) + "[-12.50,105.25,-0.75]=" + std::to_string(i) + ".5 ";
  }
  line += "le_us=12345 est[-3.10,-42.00,0.00,7]";
  DwmMeasurement m;
  ASSERT_EQ(decodeDwmLine(line, m), DwmLineStatus::kMeasurement);
  ASSERT_EQ(m.ranges.size(), 12u);
  EXPECT_DOUBLE_EQ(m.ranges[11].x, -12.5);
  EXPECT_DOUBLE_EQ(m.ranges[11].y, 105.25);
  EXPECT_DOUBLE_EQ(m.ranges[11].range, 11.5);
  EXPECT_DOUBLE_EQ(m.position.y, -42.0);
  EXPECT_EQ(m.position.quality, 7);
  EXPECT_EQ(m.computation_time_us, 12345u);
}

TEST(Dwm1001Decoder, IgnoresShellChatter) {
  DwmMeasurement m;
  for (const char* line :
       {"", "   ", "dwm> ", "dwm> les", "dwm> si", "les", "lec",
        "DWM1001 TWR Real Time Location System", "Copyright :  2016-2019 LEAPS and Decawave",
        "Help      :  ? or help", "[000007.930 INF] sys: fw2 fw_ver=x01030001 cfg_ver=x00010700",
        "[000008.340 INF] cfg: sync=0 fwup=0 ble=1 leds=1 label=DW5722", "DIST,0"}) {
    EXPECT_EQ(decodeDwmLine(line, m), DwmLineStatus::kIgnored) << line;
  }
}

TEST(Dwm1001Decoder, RejectsTruncatedMergedAndInconsistentLines) {
  DwmMeasurement m;
  const std::vector<std::string> bad = {
      kLes.substr(0, 30),                     // cut inside an anchor
      kLes.substr(0, kLes.size() - 1),        // est without ']'
      kLes.substr(20),                        // start lost
      kLes.substr(0, 60) + kLes,              // two lines run together
      kLes + kLes,                            // est followed by more
      kLec.substr(0, kLec.size() - 4),        // POS quality missing
      kLec.substr(0, 40),                     // cut inside anchor 1
      kLec + "," + kLec,                      // merged lec lines
      "DIST,3,AN0,1151,5.00,8.00,2.25,6.48",  // count says 3, one listed
      "DIST,1,AN0,1151,5.00,8.00,2.25,6.48,AN1,0CA8,0.00,8.00,2.25,6.51",  // count 1, two
      "DIST,2,AN0,1151,5.00,8.00,2.25,6.48,AN2,0CA8,0.00,8.00,2.25,6.51",  // AN index gap
      "DIST,1,AN0,1151,5.00,8.00,2.25,6.48,",                              // trailing empty field
      "POS,2.57,1.98,1.68",                                                // lep without quality
      "POS,nan,1.98,1.68,100",                                             // not finite
      "1151[5.00,8.00]=6.48",                                              // two coordinates
      "115[5.00,8.00,2.25]=6.48",                                          // 3-digit ID
      "le_us=2576 1151[5.00,8.00,2.25]=6.48",                              // anchors after le_us
      "1151[5.00,8.00,2.25]=6.48 le_us=25x6",                              // bad integer
      "8.00,2.25,6.48,AN1,0CA8",                                           // lec fragment
  };
  for (const std::string& line : bad) {
    const DwmLineStatus status = decodeDwmLine(line, m);
    EXPECT_TRUE(status == DwmLineStatus::kMalformed || status == DwmLineStatus::kCountMismatch)
        << line << " -> " << toString(status);
  }
  EXPECT_EQ(decodeDwmLine("DIST,3,AN0,1151,5.00,8.00,2.25,6.48", m), DwmLineStatus::kCountMismatch);
}

// A long plain number as a device may print it: `digits` digits, then ".00".
std::string plainNumber(std::size_t digits) {
  return "1" + std::string(digits - 1, '0') + ".00";
}

// Well-formed lines carrying a value no module can report: each is rejected as
// implausible (not malformed), and the next good line on the same output still decodes.
TEST(Dwm1001Decoder, RejectsImplausibleValuesAndRecovers) {
  const std::string lec_head = "DIST,2,AN0,1151,5.00,8.00,2.25,";
  const std::string lec_tail = ",AN1,0CA8,0.00,8.00,2.25,6.51,POS,2.57,1.98,1.68,100";
  const std::vector<std::pair<std::string, std::string>> implausible = {
      {lec_head + plainNumber(155) + lec_tail, "range 1e154 as 155 plain digits"},
      {lec_head + "300.01" + lec_tail, "range just beyond 300 m"},
      {lec_head + "-6.48" + lec_tail, "negative range"},
      {lec_head + "-0.01" + lec_tail, "slightly negative range"},
      {"DIST,1,AN0,1151,10000.01,8.00,2.25,6.48", "anchor x beyond 10 km"},
      {"DIST,1,AN0,1151,5.00,-25000.00,2.25,6.48", "anchor y beyond -10 km"},
      {"DIST,1,AN0,1151,5.00,8.00," + plainNumber(40) + ",6.48", "anchor z 1e39"},
      {"DIST,1,AN0,1151,5.00,8.00,2.25,6.48,POS,12000.00,1.98,1.68,100", "position x"},
      {"DIST,1,AN0,1151,5.00,8.00,2.25,6.48,POS,2.57,1.98,1.68,101", "lec quality 101"},
      {"POS,2.57,1.98,1.68,101", "lep quality 101"},
      {"POS,2.57,1.98,1.68,-1", "lep quality -1"},
      {"POS,2.57,-" + plainNumber(20) + ",1.68,100", "lep position y -1e19"},
      {"1151[5.00,8.00,2.25]=" + plainNumber(155) + " le_us=2576 est[2.57,1.98,1.68,100]",
       "les range 1e154"},
      {"1151[5.00,8.00,2.25]=-6.48", "les negative range"},
      {"1151[5.00,8.00,2.25]=512.00 le_us=2576", "les range 512 m"},
      {"1151[5.00,8.00,99999.00]=6.48", "les anchor z 100 km"},
      {"1151[5.00,8.00,2.25]=6.48 le_us=2576 est[2.57,1.98,1.68,255]", "les quality 255"},
      {"1151[5.00,8.00,2.25]=6.48 le_us=2576 est[2.57,1.98,-10000.50,100]", "les est z"},
  };
  DwmMeasurement m;
  for (const auto& [line, what] : implausible) {
    EXPECT_EQ(decodeDwmLine(line, m), DwmLineStatus::kImplausible) << what << ": " << line;
    ASSERT_EQ(decodeDwmLine(kLec, m), DwmLineStatus::kMeasurement) << "after " << what;
    expectThesisRanges(m);
  }
  EXPECT_STREQ(toString(DwmLineStatus::kImplausible), "implausible value");
}

TEST(Dwm1001Decoder, AcceptsValuesAtThePlausibilityBounds) {
  DwmMeasurement m;
  ASSERT_EQ(decodeDwmLine("DIST,2,AN0,1151,10000.00,-10000.00,0.00,300.00,AN1,0CA8,0.00,8.00,"
                          "2.25,0.00,POS,-10000.00,10000.00,0.00,0",
                          m),
            DwmLineStatus::kMeasurement);
  EXPECT_DOUBLE_EQ(m.ranges[0].range, 300.0);
  EXPECT_DOUBLE_EQ(m.ranges[1].range, 0.0);
  EXPECT_DOUBLE_EQ(m.ranges[0].y, -10000.0);
  EXPECT_EQ(m.position.quality, 0);
}

// A cut line stays malformed even when the part that survived holds an absurd value:
// structure is judged first.
TEST(Dwm1001Decoder, StructureIsJudgedBeforeValues) {
  DwmMeasurement m;
  EXPECT_EQ(decodeDwmLine("DIST,3,AN0,1151,5.00,8.00,2.25,-6.48", m),
            DwmLineStatus::kCountMismatch);
  EXPECT_EQ(decodeDwmLine("POS,2.57,1.98,1.68,101,", m), DwmLineStatus::kMalformed);
  EXPECT_EQ(decodeDwmLine("POS,2.57,1.98,1.68,+5", m), DwmLineStatus::kMalformed);
  EXPECT_EQ(decodeDwmLine("POS,2.57,1.98,1.68," + std::string(30, '9'), m),
            DwmLineStatus::kMalformed);  // does not even fit an integer
}

// Every real line, split into two chunks at every byte boundary, must come out of the
// framer whole, stamped with the arrival time of its first byte, and decode.
TEST(Dwm1001Decoder, SplitAtEveryByteThroughFramer) {
  for (const std::string& line : {kLes, kLec, kLep}) {
    const std::string wire = line + "\r\n";
    for (std::size_t cut = 0; cut <= wire.size(); ++cut) {
      LineFramer framer;
      std::vector<std::string> lines;
      std::vector<double> stamps;
      auto sink = [&](std::string_view l, double t) {
        lines.emplace_back(l);
        stamps.push_back(t);
      };
      framer.feed(wire.data(), cut, 1.0, sink);
      framer.feed(wire.data() + cut, wire.size() - cut, 2.0, sink);
      ASSERT_EQ(lines.size(), 1u) << "cut " << cut;
      EXPECT_EQ(lines[0], line);
      EXPECT_EQ(stamps[0], cut == 0 ? 2.0 : 1.0);
      DwmMeasurement m;
      EXPECT_EQ(decodeDwmLine(lines[0], m), DwmLineStatus::kMeasurement) << "cut " << cut;
    }
  }
}

}  // namespace
}  // namespace radio_follow::drivers
