// SPDX-License-Identifier: BSD-3-Clause
// Decoder tests: packets built from the documented layout (doc/tdoa_protocol.md), plus
// hand-written bytes, and one test per rejection reason.
#include "radio_follow/drivers/tdoa_packet.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "radio_follow/drivers/tdoa_packet_builder.hpp"

namespace radio_follow {
namespace drivers {
namespace {

using Bytes = std::vector<std::uint8_t>;

TdoaDecodeError decode(const Bytes& bytes, TdoaReport* report) {
  return decodeTdoaPacket(bytes.data(), bytes.size(), report);
}

Bytes fullPacket() {
  return TdoaPacketBuilder(0x0000000000002001ULL, 42)
      .mac(0x5A84)
      .payload({0xAA, 0xBB})
      .timestamp(0x0000001234567890ULL, 77)
      .quality(-81.25, -90.5, 3, 36.5)
      .radio(0x123456, 0xABCDEF, 5, 0x2, 0x6)
      .build();
}

TEST(TdoaPacket, HandWrittenBytesDecodeLittleEndian) {
  // Written out by hand from the layout, independent of the builder.
  const Bytes bytes{
      0x02, 0x01, 0x04, 0x03, 0x06, 0x05, 0x08, 0x07,  // magic
      0x02, 0x20, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // address 0x2002
      0x34, 0x12, 0x78, 0x56,                          // platform 0x1234, version 0x5678
      0x18, 0x00, 0x09, 0x01,                          // length 24, sequence 9, 1 TLV
      0xCD, 0xAB, 0x01, 0xEF,                          // header CRC, frame CRC
      0x03, 0x00, 0xFF, 0xFF, 0x10, 0x00, 0x00, 0x00,  // type 3 (upper bytes ignored), len 16
      0x01, 0x02, 0x03, 0x04, 0x05, 0x00, 0x00, 0x00,  // rx ticks 0x0504030201
      0x10, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // variance 16
  };
  TdoaReport r;
  ASSERT_EQ(decode(bytes, &r), TdoaDecodeError::kOk);
  EXPECT_EQ(r.anchor_address, 0x2002u);
  EXPECT_EQ(r.platform, 0x1234u);
  EXPECT_EQ(r.version, 0x5678u);
  EXPECT_EQ(r.length, 24u);
  EXPECT_EQ(r.sequence, 9u);
  EXPECT_EQ(r.tlv_count, 1u);
  EXPECT_EQ(r.header_crc, 0xABCDu);
  EXPECT_EQ(r.frame_crc, 0xEF01u);
  ASSERT_TRUE(r.has_timestamp);
  EXPECT_EQ(r.rx_ticks, 0x0504030201ULL);
  EXPECT_EQ(r.rx_variance, 16u);
  EXPECT_FALSE(r.has_tag);
}

TEST(TdoaPacket, DecodesEveryKnownTlv) {
  const Bytes bytes = fullPacket();
  TdoaReport r;
  ASSERT_EQ(decode(bytes, &r), TdoaDecodeError::kOk);
  EXPECT_EQ(r.anchor_address, 0x2001u);
  EXPECT_EQ(r.sequence, 42u);
  EXPECT_EQ(r.tlv_count, 5u);
  ASSERT_TRUE(r.has_tag);
  EXPECT_EQ(r.tag, 0x5A84u);
  EXPECT_EQ(tdoaTagIdString(r.tag), "5A84");
  ASSERT_EQ(r.payload_size, 2u);
  EXPECT_EQ(bytes[r.payload_offset], 0xAA);
  EXPECT_EQ(bytes[r.payload_offset + 1], 0xBB);
  EXPECT_EQ(r.rx_ticks, 0x0000001234567890ULL);
  EXPECT_EQ(r.rx_variance, 77u);
  ASSERT_TRUE(r.has_quality);
  EXPECT_DOUBLE_EQ(r.rssi_dbm, -81.25);
  EXPECT_DOUBLE_EQ(r.first_path_dbm, -90.5);
  EXPECT_EQ(r.los_indicator, 3u);
  EXPECT_DOUBLE_EQ(r.temperature_c, 36.5);
  ASSERT_TRUE(r.has_radio);
  EXPECT_EQ(r.rtto, 0x123456u);
  EXPECT_EQ(r.integrator, 0xABCDEFu);
  EXPECT_EQ(r.channel, 5u);
  EXPECT_EQ(r.prf, 2u);
  EXPECT_EQ(r.bitrate, 6u);
  EXPECT_EQ(r.unknown_tlvs, 0u);
}

TEST(TdoaPacket, TagIdComesFromMacBytesLikeTheReference) {
  // The reference reverses the MAC, renders hex and takes characters 6..9: for an 8-byte
  // MAC b0..b7 that is b4 b3.
  const Bytes mac{0x00, 0x11, 0x22, 0x0C, 0xA8, 0x55, 0x66, 0x77};
  TdoaReport r;
  ASSERT_EQ(decode(TdoaPacketBuilder(1, 0).rawTlv(1, mac).build(), &r), TdoaDecodeError::kOk);
  EXPECT_EQ(tdoaTagIdString(r.tag), "A80C");
  EXPECT_EQ(tdoaAddressString(0x2001), "0000000000002001");
}

TEST(TdoaPacket, SkipsBytesBeforeTheMagicAndIgnoresBytesAfterTheLength) {
  Bytes bytes{0xFF, 0x02, 0x01, 0x00};
  const Bytes packet = fullPacket();
  bytes.insert(bytes.end(), packet.begin(), packet.end());
  bytes.push_back(0xEE);
  TdoaReport r;
  ASSERT_EQ(decode(bytes, &r), TdoaDecodeError::kOk);
  EXPECT_EQ(r.tag, 0x5A84u);
  EXPECT_EQ(bytes[r.payload_offset], 0xAA);  // offsets are into the whole datagram
}

TEST(TdoaPacket, UnknownTlvIsSkippedByItsLength) {
  const Bytes bytes =
      TdoaPacketBuilder(1, 0).rawTlv(9, {1, 2, 3}).timestamp(1000).rawTlv(0, {}).build();
  TdoaReport r;
  ASSERT_EQ(decode(bytes, &r), TdoaDecodeError::kOk);
  EXPECT_EQ(r.unknown_tlvs, 2u);
  EXPECT_EQ(r.rx_ticks, 1000u);
}

TEST(TdoaPacket, LongerKnownTlvIsReadForItsFixedFieldsAndSkipped) {
  Bytes ts(20, 0);
  ts[0] = 0x42;
  const Bytes bytes = TdoaPacketBuilder(1, 0).rawTlv(3, ts).mac(0x1234).build();
  TdoaReport r;
  ASSERT_EQ(decode(bytes, &r), TdoaDecodeError::kOk);
  EXPECT_EQ(r.rx_ticks, 0x42u);
  EXPECT_EQ(r.tag, 0x1234u);
}

TEST(TdoaPacket, RejectsEmptyAndMissingMagic) {
  TdoaReport r;
  EXPECT_EQ(decode({}, &r), TdoaDecodeError::kNoMagic);
  Bytes bytes = fullPacket();
  bytes[3] ^= 0x01;
  EXPECT_EQ(decode(bytes, &r), TdoaDecodeError::kNoMagic);
}

TEST(TdoaPacket, RejectsEveryTruncationOfAValidPacket) {
  const Bytes bytes = fullPacket();
  TdoaReport r;
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const TdoaDecodeError e = decodeTdoaPacket(bytes.data(), n, &r);
    if (n < kTdoaMagic.size()) {
      EXPECT_EQ(e, TdoaDecodeError::kNoMagic) << n;
    } else if (n < kTdoaHeaderSize) {
      EXPECT_EQ(e, TdoaDecodeError::kTooShort) << n;
    } else {
      EXPECT_EQ(e, TdoaDecodeError::kLengthBeyondPacket) << n;
    }
  }
}

TEST(TdoaPacket, RejectsLengthFieldBeyondPacket) {
  const Bytes good = TdoaPacketBuilder(1, 0).timestamp(5).build();
  const auto length = static_cast<std::uint16_t>(good.size() - kTdoaHeaderSize);
  TdoaReport r;
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).timestamp(5).lengthField(length + 1).build(), &r),
            TdoaDecodeError::kLengthBeyondPacket);
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).timestamp(5).lengthField(0xFFFF).build(), &r),
            TdoaDecodeError::kLengthBeyondPacket);
}

TEST(TdoaPacket, RejectsTlvHeaderOutsideDeclaredLength) {
  TdoaReport r;
  // Two TLVs claimed, one present.
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).timestamp(5).tlvCountField(2).build(), &r),
            TdoaDecodeError::kTlvTruncated);
  // Length cuts into the TLV header.
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).timestamp(5).lengthField(4).build(), &r),
            TdoaDecodeError::kTlvTruncated);
}

TEST(TdoaPacket, RejectsTlvOverrunningTheDeclaredLength) {
  TdoaReport r;
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).rawTlv(2, {1, 2, 3}, 4).build(), &r),
            TdoaDecodeError::kTlvOverrun);
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).rawTlv(7, {}, 0xFFFFFFFFu).build(), &r),
            TdoaDecodeError::kTlvOverrun);
  // The bytes are in the datagram but outside the header's length: still an overrun.
  const Bytes inner = TdoaPacketBuilder(1, 0).timestamp(5).build();
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0)
                       .timestamp(5)
                       .lengthField(static_cast<std::uint16_t>(inner.size() - kTdoaHeaderSize - 1))
                       .build(),
                   &r),
            TdoaDecodeError::kTlvOverrun);
}

TEST(TdoaPacket, RejectsKnownTlvsShorterThanTheirFields) {
  TdoaReport r;
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).rawTlv(3, Bytes(15, 0)).build(), &r),
            TdoaDecodeError::kTlvTooShort);
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).rawTlv(4, Bytes(7, 0)).build(), &r),
            TdoaDecodeError::kTlvTooShort);
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).rawTlv(5, Bytes(7, 0)).build(), &r),
            TdoaDecodeError::kTlvTooShort);
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).rawTlv(1, Bytes(4, 0)).build(), &r),
            TdoaDecodeError::kTlvTooShort);
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).rawTlv(1, Bytes(17, 0)).build(), &r),
            TdoaDecodeError::kTlvTooShort);
}

TEST(TdoaPacket, RejectsBytesLeftOverAfterTheTlvs) {
  TdoaReport r;
  EXPECT_EQ(decode(TdoaPacketBuilder(1, 0).timestamp(5).tlvCountField(0).build(), &r),
            TdoaDecodeError::kLengthMismatch);
}

// The quality TLV's powers must be ones a DW1000 can report (plausibility.hpp); a report
// with an impossible one is rejected whole, and the next good report still decodes.
TEST(TdoaPacket, RejectsImplausibleQualityAndRecovers) {
  const auto withQuality = [](double rssi, double first_path) {
    return TdoaPacketBuilder(0x2001, 42)
        .mac(0x5A84)
        .timestamp(0x1234567890ULL)
        .quality(rssi, first_path, 3, 36.5)
        .build();
  };
  TdoaReport r;
  for (const auto& [rssi, first_path] : std::vector<std::pair<double, double>>{
           {12.5, -90.5}, {-81.25, 0.01}, {-127.01, -90.5}, {-81.25, -327.68}, {327.67, -1.0}}) {
    EXPECT_EQ(decode(withQuality(rssi, first_path), &r), TdoaDecodeError::kImplausible)
        << rssi << " / " << first_path << " dBm";
    ASSERT_EQ(decode(fullPacket(), &r), TdoaDecodeError::kOk);
    EXPECT_DOUBLE_EQ(r.rssi_dbm, -81.25);
    EXPECT_EQ(r.tag, 0x5A84);
  }
  EXPECT_EQ(decode(withQuality(-127.0, 0.0), &r), TdoaDecodeError::kOk);  // the bounds
  EXPECT_STREQ(toString(TdoaDecodeError::kImplausible), "implausible_value");
  // Structure first: a truncated packet with an absurd power is truncated, not implausible.
  Bytes cut = withQuality(12.5, -90.5);
  cut.resize(cut.size() - 1);
  EXPECT_EQ(decode(cut, &r), TdoaDecodeError::kLengthBeyondPacket);
}

TEST(TdoaPacket, ErrorNamesAreDistinct) {
  for (std::size_t i = 0; i < kTdoaDecodeErrorCount; ++i) {
    for (std::size_t j = i + 1; j < kTdoaDecodeErrorCount; ++j) {
      EXPECT_STRNE(toString(static_cast<TdoaDecodeError>(i)),
                   toString(static_cast<TdoaDecodeError>(j)));
    }
  }
}

}  // namespace
}  // namespace drivers
}  // namespace radio_follow
