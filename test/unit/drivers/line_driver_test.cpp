// SPDX-License-Identifier: BSD-3-Clause
// The serial-line drivers' bookkeeping without ROS: real DWM1001 and +UUDF lines split at
// every byte boundary, verdicts counted as the diagnostics report them, a reconnect that
// drops the old connection's partial line, and silence measured from the last byte.
#include "radio_follow/drivers/line_driver.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "radio_follow/drivers/dwm1001_decoder.hpp"
#include "radio_follow/drivers/uudf_decoder.hpp"

namespace radio_follow::drivers {
namespace {

// A capture of a module streaming `lec` after the shell dialogue, with one cut line.
const std::string kDwmStream =
    "dwm> lec\r\n"
    "DIST,2,AN0,1151,5.00,8.00,2.25,6.48,AN1,0CA8,0.00,8.00,2.25,6.51,POS,2.57,1.98,1.68,100\r\n"
    "DIST,2,AN0,1151,5.00,8.00,2.25,6.4\r\n"
    "DIST,1,AN0,1151,5.00,8.00,2.25,901.0\r\n"
    "DIST,1,AN0,1151,5.00,8.00,2.25,6.50\r\n";

// Decodes like the dwm1001_driver node and counts the verdict; returns the measurements.
std::vector<double> feedDwm(LineDriver& driver, const std::string& text, std::size_t chunk) {
  std::vector<double> stamps;
  DwmMeasurement out;
  for (std::size_t pos = 0; pos < text.size(); pos += chunk) {
    const double now = static_cast<double>(pos);
    driver.onBytes(text.data() + pos, std::min(chunk, text.size() - pos), now,
                   [&](std::string_view line, double stamp) {
                     const LineVerdict verdict =
                         verdictOf(decodeDwmLine(line, out), DwmLineStatus::kMeasurement);
                     driver.count(verdict);
                     if (verdict == LineVerdict::kMeasurement) {
                       stamps.push_back(stamp);
                     }
                   });
  }
  return stamps;
}

TEST(LineDriver, CountsEveryVerdictWhateverTheChunking) {
  for (std::size_t chunk = 1; chunk <= kDwmStream.size(); ++chunk) {
    LineDriver driver(1024);
    driver.onConnected(0.0, 0);
    const std::vector<double> stamps = feedDwm(driver, kDwmStream, chunk);
    const DriverStatsSnapshot s = driver.stats().snapshot();
    ASSERT_EQ(stamps.size(), 2u) << "chunk " << chunk;
    EXPECT_EQ(s.ignored, 1u);      // the prompt with the command echo
    EXPECT_EQ(s.rejected, 2u);     // the cut line and the 901 m range
    EXPECT_EQ(s.implausible, 1u);  // of them: the 901 m range
    EXPECT_EQ(s.bytes, kDwmStream.size());
    EXPECT_EQ(s.last_data_time, static_cast<double>((kDwmStream.size() - 1) / chunk * chunk));
    // Stamped with the receive time of the chunk that carried the line's first byte.
    const std::size_t second = kDwmStream.find("DIST,2");
    EXPECT_EQ(stamps[0], static_cast<double>(second / chunk * chunk));
  }
}

TEST(LineDriver, MapsEachDecodersStatus) {
  EXPECT_EQ(verdictOf(UudfLineStatus::kEvent, UudfLineStatus::kEvent), LineVerdict::kMeasurement);
  EXPECT_EQ(verdictOf(UudfLineStatus::kIgnored, UudfLineStatus::kEvent), LineVerdict::kIgnored);
  EXPECT_EQ(verdictOf(UudfLineStatus::kMalformed, UudfLineStatus::kEvent), LineVerdict::kRejected);
  EXPECT_EQ(verdictOf(UudfLineStatus::kImplausible, UudfLineStatus::kEvent),
            LineVerdict::kImplausible);
  EXPECT_EQ(verdictOf(DwmLineStatus::kCountMismatch, DwmLineStatus::kMeasurement),
            LineVerdict::kRejected);
  UudfEvent event;
  EXPECT_EQ(verdictOf(decodeUudfLine("+UUDF:CCF9578E0D8A,-42,20,0,-43,37,\"CCF9578E0D89\",\"\","
                                     "15869,23",
                                     event),
                      UudfLineStatus::kEvent),
            LineVerdict::kMeasurement);
}

TEST(LineDriver, ReconnectDropsThePartialLineOfTheOldConnection) {
  LineDriver driver(1024);
  driver.onConnected(1.0, 0);
  std::vector<std::string> lines;
  auto sink = [&](std::string_view line, double) { lines.emplace_back(line); };
  const std::string cut = "DIST,1,AN0,1151,5.0";
  driver.onBytes(cut.data(), cut.size(), 1.5, sink);
  EXPECT_EQ(driver.pending(), cut);
  driver.onDisconnected();
  EXPECT_FALSE(driver.stats().connected);
  driver.onConnected(4.0, 1);
  EXPECT_TRUE(driver.pending().empty());
  const std::string next = "POS,1,2,3,4\r\n";
  driver.onBytes(next.data(), next.size(), 4.5, sink);
  EXPECT_EQ(lines, std::vector<std::string>{"POS,1,2,3,4"});
  EXPECT_EQ(driver.stats().reconnects, 1u);
}

TEST(LineDriver, SilentOnlyWhileConnectedAndQuiet) {
  LineDriver driver(1024);
  EXPECT_FALSE(driver.silent(100.0, 2.0));  // never connected
  driver.onConnected(10.0, 0);
  EXPECT_FALSE(driver.silent(11.9, 2.0));
  EXPECT_TRUE(driver.silent(12.1, 2.0));  // counted from the connect
  driver.onBytes("x", 1, 12.5, [](std::string_view, double) {});
  EXPECT_FALSE(driver.silent(14.0, 2.0));
  EXPECT_TRUE(driver.silent(14.6, 2.0));
  driver.onDisconnected();
  EXPECT_FALSE(driver.silent(20.0, 2.0));  // absent is not silent: it is disconnected
}

TEST(LineDriver, CountsOverflowsFilteredDropsAndPublished) {
  LineDriver driver(64);
  driver.onConnected(0.0, 0);
  const std::string garbage = std::string(100, 'x') + "\n";
  driver.onBytes(garbage.data(), garbage.size(), 0.1, [](std::string_view, double) {});
  EXPECT_EQ(driver.stats().overflows, 1u);
  driver.count(LineVerdict::kFiltered);
  driver.count(LineVerdict::kMeasurement);  // counted when published, not here
  EXPECT_EQ(driver.stats().filtered, 1u);
  EXPECT_EQ(driver.stats().rejected, 0u);
  driver.onQueued(true, 1);
  driver.onQueued(false, 7);  // the queue was full: its oldest item was dropped
  EXPECT_EQ(driver.stats().dropped, 1u);
  EXPECT_EQ(driver.stats().queue_peak, 7u);
  EXPECT_TRUE(driver.onPublished());
  EXPECT_FALSE(driver.onPublished());
  EXPECT_EQ(driver.stats().messages, 2u);
}

}  // namespace
}  // namespace radio_follow::drivers
