// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/fault_speech.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {
namespace {

using Texts = std::vector<std::string>;

// Names and hardware ids as the nodes publish them (doc/diagnostics.md).
ReportedStatus uwb(StatusLevel level, const std::string& message) {
  return {"/dwm1001_front: dwm1001 /dev/dwm1001_5722", level, message,
          "/dev/dwm1001_5722 (module 5722)"};
}

ReportedStatus locator(StatusLevel level, const std::string& message) {
  return {"/locator: locator", level, message, "layout spot.yaml, frame base_link"};
}

FaultSpeechParams params(double hold = 2.0, double silence = 5.0) {
  FaultSpeechParams p;
  p.hold_time = hold;
  p.silence_timeout = silence;
  return p;
}

/// Feeds `status` once a second (the diagnostics rate) from `from` to `to` inclusive and
/// collects what became due.
Texts feed(FaultSpeech& speech, const ReportedStatus& status, double from, double to) {
  Texts said;
  for (double t = from; t <= to + 1e-9; t += 1.0) {
    speech.observe(status, t);
    for (auto& text : speech.due(t)) {
      said.push_back(text);
    }
  }
  return said;
}

TEST(FaultSpeech, NamesDriversAndLocatorAndIgnoresTheRest) {
  EXPECT_EQ(FaultSpeech::speakerName(uwb(StatusLevel::kOk, "streaming")), "UWB module 5722");
  EXPECT_EQ(FaultSpeech::speakerName({"/aoa_front: ublox aoa /dev/aoa_front", StatusLevel::kOk,
                                      "streaming", "/dev/aoa_front (board aoa_front)"}),
            "AoA board front");
  // Without a module id the port names it.
  EXPECT_EQ(FaultSpeech::speakerName({"/uwb: dwm1001 /dev/ttyACM0", StatusLevel::kOk, "", ""}),
            "UWB module ttyACM0");
  EXPECT_EQ(FaultSpeech::speakerName(
                {"/tdoa_driver: TDoA anchors", StatusLevel::kOk, "", "tdoa udp 0.0.0.0:5050"}),
            "TDoA anchors");
  EXPECT_EQ(FaultSpeech::speakerName(locator(StatusLevel::kOk, "tracking")), "Locator");
  EXPECT_EQ(FaultSpeech::speakerName({"/locator: locator output /target topic status",
                                      StatusLevel::kWarn, "Frequency too low.", ""}),
            "");
  EXPECT_EQ(FaultSpeech::speakerName(
                {"/velocity_controller: controller", StatusLevel::kWarn, "target_lost", ""}),
            "");
  FaultSpeech speech(params());
  EXPECT_FALSE(speech.observe({"/x: controller", StatusLevel::kError, "broken", ""}, 0.0));
  EXPECT_TRUE(speech.observe(uwb(StatusLevel::kOk, "streaming"), 0.0));
}

TEST(FaultSpeech, DeviceLostIsSpokenAfterHoldAndBackWhenItReturns) {
  FaultSpeech speech(params(2.0));
  EXPECT_EQ(feed(speech, uwb(StatusLevel::kOk, "streaming"), 0.0, 5.0), Texts{});
  // Unplugged at t = 6: said once, two seconds later, not repeated while it lasts.
  EXPECT_EQ(feed(speech, uwb(StatusLevel::kError, "device not connected"), 6.0, 7.0), Texts{});
  EXPECT_EQ(feed(speech, uwb(StatusLevel::kError, "device not connected"), 8.0, 20.0),
            Texts{"UWB module 5722 lost."});
  EXPECT_EQ(feed(speech, uwb(StatusLevel::kOk, "streaming"), 21.0, 30.0),
            Texts{"UWB module 5722 back."});
}

TEST(FaultSpeech, AFaultShorterThanTheHoldTimeSaysNothing) {
  FaultSpeech speech(params(2.0));
  feed(speech, uwb(StatusLevel::kOk, "streaming"), 0.0, 3.0);
  EXPECT_EQ(feed(speech, uwb(StatusLevel::kWarn, "no data from the device"), 4.0, 4.0), Texts{});
  EXPECT_EQ(feed(speech, uwb(StatusLevel::kOk, "streaming"), 5.0, 15.0), Texts{});
}

TEST(FaultSpeech, SilentDeviceAndOtherWarnings) {
  FaultSpeech speech(params(1.0));
  EXPECT_EQ(feed(speech, uwb(StatusLevel::kWarn, "no data from the device"), 0.0, 3.0),
            Texts{"No data from UWB module 5722."});
  EXPECT_EQ(
      feed(speech, uwb(StatusLevel::kWarn, "dropping measurements"), 4.0, 6.0),
      (Texts{"UWB module 5722 sends data again.", "UWB module 5722: dropping measurements."}));
  // A warning with no named recovery ends silently.
  EXPECT_EQ(feed(speech, uwb(StatusLevel::kOk, "streaming"), 7.0, 10.0), Texts{});
}

TEST(FaultSpeech, LocatorTargetStatesAndSilentInputs) {
  FaultSpeech speech(params(1.0));
  EXPECT_EQ(feed(speech, locator(StatusLevel::kOk, "tracking"), 0.0, 2.0), Texts{});
  EXPECT_EQ(
      feed(speech, locator(StatusLevel::kWarn, "target lost; silent inputs: /aoa/left/bearing"),
           3.0, 5.0),
      (Texts{"Locator lost the target.", "Locator: no data from left bearing."}));
  // Lost -> uncertain is a new sentence; the input stays silent (said once).
  EXPECT_EQ(feed(speech, locator(StatusLevel::kWarn, "DEGRADED; silent inputs: /aoa/left/bearing"),
                 6.0, 8.0),
            Texts{"Target position uncertain."});
  EXPECT_EQ(feed(speech, locator(StatusLevel::kOk, "tracking"), 9.0, 12.0),
            (Texts{"Target found.", "Locator: data from left bearing again."}));
  EXPECT_EQ(feed(speech, locator(StatusLevel::kWarn, "AMBIGUOUS"), 13.0, 15.0),
            Texts{"Target may be at its mirror image."});
  EXPECT_EQ(feed(speech, locator(StatusLevel::kWarn, "HEADING_ONLY"), 16.0, 18.0),
            Texts{"Only the target's direction is known."});
}

TEST(FaultSpeech, FoundIsSaidEvenWhenTheLastStateWasNeverSpoken) {
  FaultSpeech speech(params(2.0));
  feed(speech, locator(StatusLevel::kOk, "tracking"), 0.0, 1.0);
  EXPECT_EQ(feed(speech, locator(StatusLevel::kWarn, "target lost"), 2.0, 5.0),
            Texts{"Locator lost the target."});
  // One second uncertain (too short to say), then tracking: the loss was said, so its
  // end is owed.
  EXPECT_EQ(feed(speech, locator(StatusLevel::kWarn, "DEGRADED"), 6.0, 6.0), Texts{});
  EXPECT_EQ(feed(speech, locator(StatusLevel::kOk, "tracking"), 7.0, 10.0), Texts{"Target found."});
}

TEST(FaultSpeech, ANodeThatStopsReportingIsSaidAndItsReturn) {
  FaultSpeech speech(params(1.0, 5.0));
  EXPECT_EQ(feed(speech, uwb(StatusLevel::kError, "device not connected"), 0.0, 2.0),
            Texts{"UWB module 5722 lost."});
  Texts said;
  for (double t = 3.0; t <= 12.0; t += 1.0) {
    for (auto& text : speech.due(t)) {
      said.push_back(text);
    }
  }
  // Last report at 2 s: stale once 5 s have passed without one (t = 8), said a hold time
  // later. What it said before is dropped without a "back".
  EXPECT_EQ(said, Texts{"UWB module 5722 stopped reporting."});
  EXPECT_EQ(feed(speech, uwb(StatusLevel::kOk, "streaming"), 13.0, 16.0),
            Texts{"UWB module 5722 reporting again."});
}

TEST(FaultSpeech, SourcesAreKeptApartAndSpokenInOrderOfOnset) {
  FaultSpeech speech(params(1.0));
  const ReportedStatus board{"/aoa_left: ublox aoa /dev/aoa_left", StatusLevel::kError,
                             "device not connected", "/dev/aoa_left (board aoa_left)"};
  speech.observe(board, 0.0);
  speech.observe(uwb(StatusLevel::kError, "device not connected"), 0.5);
  EXPECT_EQ(speech.due(0.9), Texts{});
  EXPECT_EQ(speech.due(2.0), (Texts{"AoA board left lost.", "UWB module 5722 lost."}));
}

TEST(FaultSpeech, ValidateNamesTheParameter) {
  FaultSpeechParams p;
  p.hold_time = -1.0;
  try {
    p.validate("~");
    FAIL() << "negative hold_time accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "~hold_time");
  }
  p = FaultSpeechParams{};
  p.silence_timeout = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(p.validate(), ParamError);
  p.silence_timeout = 0.0;
  EXPECT_THROW(FaultSpeech{p}, ParamError);
}

}  // namespace
}  // namespace control
}  // namespace radio_follow
