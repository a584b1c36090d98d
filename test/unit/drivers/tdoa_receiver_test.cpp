// SPDX-License-Identifier: BSD-3-Clause
// Time differences from a simulated blink: a tag at a known position, anchors whose
// clocks are synchronised to the master's sync frame (so each runs late by its time of
// flight from the master), timestamps quantised to ticks.
#include "radio_follow/drivers/tdoa_receiver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/drivers/tdoa_packet_builder.hpp"

namespace radio_follow {
namespace drivers {
namespace {

// The reference's anchor layout (brozb/uwb_tdoa config/tdoa.yaml), master 0x2000.
TdoaDifferenceConfig layout() {
  TdoaDifferenceConfig c;
  c.anchors = {{"front_left", 0x2000, {0.29, 0.165, 0.135}},
               {"front_right", 0x2002, {0.29, -0.165, 0.135}},
               {"back", 0x2001, {-0.37, 0.0, 0.135}}};
  c.master = 0;
  c.reference = 0;
  return c;
}

// Anchor i's timestamp of a blink sent at `t0` seconds from `tag`.
std::uint64_t rxTicks(const TdoaDifferenceConfig& c, std::size_t i, const Eigen::Vector3d& tag,
                      double t0) {
  const double flight = (tag - c.anchors[i].position).norm() / kSpeedOfLight;
  const double sync_lag =
      (c.anchors[i].position - c.anchors[c.master].position).norm() / kSpeedOfLight;
  return static_cast<std::uint64_t>(std::llround((t0 + flight - sync_lag) * kTdoaTickFrequency));
}

std::vector<std::uint8_t> report(const TdoaDifferenceConfig& c, std::size_t i, std::uint16_t tag,
                                 std::uint8_t seq, std::uint64_t ticks) {
  return TdoaPacketBuilder(c.anchors[i].address, seq).mac(tag).timestamp(ticks).build();
}

double expected(const TdoaDifferenceConfig& c, std::size_t a, const Eigen::Vector3d& tag) {
  return (tag - c.anchors[a].position).norm() - (tag - c.anchors[c.reference].position).norm();
}

// One tick is 4.7 mm of light travel; two rounded timestamps differ by at most that.
constexpr double kTickMetres = kSpeedOfLight / kTdoaTickFrequency;

void checkBlink(const TdoaDifferenceConfig& c, const TdoaBlink& blink, const Eigen::Vector3d& tag) {
  ASSERT_EQ(blink.differences.size(), c.anchors.size() - 1);
  for (const auto& d : blink.differences) {
    EXPECT_EQ(d.anchor_b, c.reference);
    EXPECT_NEAR(d.distance_difference, expected(c, d.anchor_a, tag), kTickMetres);
    EXPECT_DOUBLE_EQ(d.variance, c.distance_variance);
  }
}

TEST(TdoaReceiver, DifferencesMatchTheGeometry) {
  for (std::size_t reference : {0u, 2u}) {
    TdoaDifferenceConfig c = layout();
    c.reference = reference;
    TdoaReceiver receiver(c, 0.05);
    const Eigen::Vector3d tag(3.0, 1.5, 1.0);
    // Beyond 2^40 ticks (17.2 s): extended counters must not cost precision.
    const double t0 = 1000.123;
    std::vector<TdoaBlink> out;
    for (std::size_t i : {2u, 0u, 1u}) {
      const auto bytes = report(c, i, 0x5A84, 17, rxTicks(c, i, tag, t0));
      receiver.onDatagram(bytes.data(), bytes.size(), 5.0, &out);
    }
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].tag, 0x5A84);
    EXPECT_DOUBLE_EQ(out[0].first_arrival, 5.0);
    checkBlink(c, out[0], tag);
    EXPECT_EQ(receiver.stats().blinks, 1u);
    EXPECT_EQ(receiver.stats().reports, 3u);
  }
}

TEST(TdoaReceiver, HandlesFortyBitCounterWrapBetweenAnchors) {
  const TdoaDifferenceConfig c = layout();
  TdoaReceiver receiver(c, 0.05);
  const Eigen::Vector3d tag(-2.0, 4.0, 0.5);
  // Choose t0 so the blink arrives just before the 2^40 wrap at anchor 0.
  const double wrap_s = std::ldexp(1.0, 40) / kTdoaTickFrequency;
  const double t0 = wrap_s - 10e-9 - (tag - c.anchors[0].position).norm() / kSpeedOfLight;
  std::vector<TdoaBlink> out;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::uint64_t ticks = rxTicks(c, i, tag, t0) & ((std::uint64_t{1} << 40) - 1);
    const auto bytes = report(c, i, 0x0CA8, 200, ticks);
    receiver.onDatagram(bytes.data(), bytes.size(), 1.0, &out);
  }
  ASSERT_EQ(out.size(), 1u);
  checkBlink(c, out[0], tag);
}

TEST(TdoaReceiver, PublishesIncompleteBlinkOnTimeoutAndDropsOneWithoutReference) {
  const TdoaDifferenceConfig c = layout();
  TdoaReceiver receiver(c, 0.05);
  const Eigen::Vector3d tag(1.0, -2.0, 0.3);
  std::vector<TdoaBlink> out;
  for (std::size_t i : {0u, 2u}) {
    const auto bytes = report(c, i, 1, 1, rxTicks(c, i, tag, 10.0));
    receiver.onDatagram(bytes.data(), bytes.size(), 1.0, &out);
  }
  for (std::size_t i : {1u, 2u}) {  // the reference (0) misses blink 2
    const auto bytes = report(c, i, 1, 2, rxTicks(c, i, tag, 10.1));
    receiver.onDatagram(bytes.data(), bytes.size(), 1.1, &out);
  }
  receiver.onTimer(1.2, &out);
  ASSERT_EQ(out.size(), 1u);
  ASSERT_EQ(out[0].differences.size(), 1u);
  EXPECT_EQ(out[0].differences[0].anchor_a, 2u);
  EXPECT_NEAR(out[0].differences[0].distance_difference, expected(c, 2, tag), kTickMetres);
  EXPECT_EQ(receiver.stats().blinks_incomplete, 1u);
  EXPECT_EQ(receiver.stats().blinks_dropped, 1u);
}

TEST(TdoaReceiver, DiscardsPhysicallyImpossibleDifference) {
  const TdoaDifferenceConfig c = layout();
  TdoaReceiver receiver(c, 0.05);
  const Eigen::Vector3d tag(2.0, 0.0, 0.0);
  std::vector<TdoaBlink> out;
  for (std::size_t i = 0; i < 3; ++i) {
    // Anchor 1 is 10 ns (3 m) late: more than its 0.33 m baseline + 0.5 m margin allow.
    const std::uint64_t late = i == 1 ? 639 : 0;
    const auto bytes = report(c, i, 1, 1, rxTicks(c, i, tag, 3.0) + late);
    receiver.onDatagram(bytes.data(), bytes.size(), 1.0, &out);
  }
  ASSERT_EQ(out.size(), 1u);
  ASSERT_EQ(out[0].differences.size(), 1u);
  EXPECT_EQ(out[0].differences[0].anchor_a, 2u);
  EXPECT_EQ(receiver.stats().implausible_differences, 1u);
}

// However far apart the anchors are configured, a difference beyond 300 m (two anchors
// that cannot both be within UWB range of the tag) is discarded and counted, and the
// blink's other difference is still published.
TEST(TdoaReceiver, DiscardsDifferenceBeyondThePhysicalBound) {
  TdoaDifferenceConfig c;
  c.anchors = {{"origin", 0x2000, {0.0, 0.0, 0.0}},
               {"far", 0x2001, {1000.0, 0.0, 0.0}},
               {"near", 0x2002, {0.0, 200.0, 0.0}}};
  TdoaReceiver receiver(c, 0.05);
  const Eigen::Vector3d tag(150.0, 0.0, 0.0);  // "far": 850 - 150 = 700 m; "near": 100 m
  std::vector<TdoaBlink> out;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto bytes = report(c, i, 1, 1, rxTicks(c, i, tag, 3.0));
    receiver.onDatagram(bytes.data(), bytes.size(), 1.0, &out);
  }
  ASSERT_EQ(out.size(), 1u);
  ASSERT_EQ(out[0].differences.size(), 1u);
  EXPECT_EQ(out[0].differences[0].anchor_a, 2u);
  EXPECT_NEAR(out[0].differences[0].distance_difference, 100.0, kTickMetres);
  EXPECT_EQ(receiver.stats().implausible_differences, 1u);
}

// Reports with an impossible quality TLV are counted under their own decode error, and
// the blink is still formed from the good ones.
TEST(TdoaReceiver, CountsImplausibleReportsAndKeepsGoing) {
  const TdoaDifferenceConfig c = layout();
  TdoaReceiver receiver(c, 0.05);
  const Eigen::Vector3d tag(1.0, 1.0, 0.0);
  std::vector<TdoaBlink> out;
  const auto bad = TdoaPacketBuilder(c.anchors[1].address, 1)
                       .mac(1)
                       .timestamp(rxTicks(c, 1, tag, 2.0))
                       .quality(25.0, -90.0, 0, 30.0)
                       .build();
  EXPECT_EQ(receiver.onDatagram(bad.data(), bad.size(), 1.0, &out), TdoaDecodeError::kImplausible);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto bytes = report(c, i, 1, 1, rxTicks(c, i, tag, 2.0));
    receiver.onDatagram(bytes.data(), bytes.size(), 1.0, &out);
  }
  ASSERT_EQ(out.size(), 1u);
  checkBlink(c, out[0], tag);
  EXPECT_EQ(receiver.stats().decode_errors[static_cast<std::size_t>(TdoaDecodeError::kImplausible)],
            1u);
  EXPECT_EQ(receiver.stats().rejected(), 1u);
}

TEST(TdoaReceiver, CountsEveryRejectionAndKeepsGoing) {
  const TdoaDifferenceConfig c = layout();
  TdoaReceiver receiver(c, 0.05);
  std::vector<TdoaBlink> out;
  const std::vector<std::uint8_t> garbage{1, 2, 3};
  receiver.onDatagram(garbage.data(), garbage.size(), 1.0, &out);
  const auto unknown = TdoaPacketBuilder(0x9999, 1).mac(1).timestamp(1).build();
  receiver.onDatagram(unknown.data(), unknown.size(), 1.0, &out);
  const auto no_tag = TdoaPacketBuilder(0x2000, 1).timestamp(1).build();
  receiver.onDatagram(no_tag.data(), no_tag.size(), 1.0, &out);
  const auto first = report(c, 0, 1, 1, 1000);
  receiver.onDatagram(first.data(), first.size(), 1.0, &out);
  receiver.onDatagram(first.data(), first.size(), 1.0, &out);
  const TdoaStats& s = receiver.stats();
  EXPECT_EQ(s.packets, 5u);
  EXPECT_EQ(s.decode_errors[static_cast<std::size_t>(TdoaDecodeError::kNoMagic)], 1u);
  EXPECT_EQ(s.unknown_anchor, 1u);
  EXPECT_EQ(s.missing_tlv, 1u);
  EXPECT_EQ(s.duplicate, 1u);
  EXPECT_EQ(s.reports, 1u);
  EXPECT_EQ(s.rejected(), 4u);
  for (std::size_t i : {1u, 2u}) {
    const auto bytes = report(c, i, 1, 1, 1000);
    receiver.onDatagram(bytes.data(), bytes.size(), 1.0, &out);
  }
  EXPECT_EQ(out.size(), 1u);
}

TEST(TdoaReceiver, ConfigurationIsValidated) {
  TdoaDifferenceConfig c = layout();
  c.reference = 3;
  EXPECT_THROW(TdoaReceiver(c, 0.05), ParamError);
  c = layout();
  c.anchors[1].address = c.anchors[0].address;
  EXPECT_THROW(TdoaReceiver(c, 0.05), ParamError);
  c = layout();
  c.anchors[2].id = "front_left";
  EXPECT_THROW(TdoaReceiver(c, 0.05), ParamError);
  c = layout();
  c.distance_variance = 0.0;
  EXPECT_THROW(TdoaReceiver(c, 0.05), ParamError);
  c.distance_variance = std::nan("");
  EXPECT_THROW(TdoaReceiver(c, 0.05), ParamError);
  c = layout();
  c.anchors[1].position.y() = -20000.0;  // beyond 10 km: not a UWB network
  EXPECT_THROW(TdoaReceiver(c, 0.05), ParamError);
  c.anchors[1].position.y() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(TdoaReceiver(c, 0.05), ParamError);
  c = layout();
  c.min_anchors = 4;
  EXPECT_THROW(TdoaReceiver(c, 0.05), ParamError);
  c = layout();
  c.anchors.resize(1);
  c.master = c.reference = 0;
  c.min_anchors = 1;
  EXPECT_THROW(TdoaReceiver(c, 0.05), ParamError);
  EXPECT_THROW(TdoaReceiver(layout(), 0.0), ParamError);
  EXPECT_NO_THROW(TdoaReceiver(layout(), 0.05));
}

TEST(TdoaDifferenceCalculator, TickDifferenceWrapsAtFortyBits) {
  const std::uint64_t top = (std::uint64_t{1} << 40) - 5;
  EXPECT_EQ(TdoaDifferenceCalculator::tickDifference(3, top), 8);
  EXPECT_EQ(TdoaDifferenceCalculator::tickDifference(top, 3), -8);
  EXPECT_EQ(TdoaDifferenceCalculator::tickDifference(1000, 10), 990);
}

}  // namespace
}  // namespace drivers
}  // namespace radio_follow
