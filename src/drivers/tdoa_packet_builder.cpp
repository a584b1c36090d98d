// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/tdoa_packet_builder.hpp"

#include <cmath>

#include "radio_follow/drivers/tdoa_packet.hpp"

namespace radio_follow {
namespace drivers {
namespace {

void appendLe(std::vector<std::uint8_t>& out, std::uint64_t value, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
  }
}

std::uint16_t fixedPoint(double value, double scale) {
  return static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(value * scale)));
}

}  // namespace

TdoaPacketBuilder::TdoaPacketBuilder(std::uint64_t anchor_address, std::uint8_t sequence)
    : address_(anchor_address), sequence_(sequence) {}

TdoaPacketBuilder& TdoaPacketBuilder::mac(std::uint16_t tag) {
  // Blink source address, least significant byte first; the tag ID sits in bytes 3, 4.
  std::vector<std::uint8_t> bytes{0xC5,
                                  sequence_,
                                  0x00,
                                  static_cast<std::uint8_t>(tag & 0xFF),
                                  static_cast<std::uint8_t>(tag >> 8),
                                  0xCA,
                                  0xDE,
                                  0x00};
  return rawTlv(static_cast<std::uint32_t>(TdoaTlvType::kMac), bytes);
}

TdoaPacketBuilder& TdoaPacketBuilder::payload(const std::vector<std::uint8_t>& bytes) {
  return rawTlv(static_cast<std::uint32_t>(TdoaTlvType::kPayload), bytes);
}

TdoaPacketBuilder& TdoaPacketBuilder::timestamp(std::uint64_t rx_ticks, std::uint64_t variance) {
  std::vector<std::uint8_t> bytes;
  appendLe(bytes, rx_ticks, 8);
  appendLe(bytes, variance, 8);
  return rawTlv(static_cast<std::uint32_t>(TdoaTlvType::kTimestamp), bytes);
}

TdoaPacketBuilder& TdoaPacketBuilder::quality(double rssi_dbm, double first_path_dbm,
                                              std::uint16_t los, double temperature_c) {
  std::vector<std::uint8_t> bytes;
  appendLe(bytes, fixedPoint(rssi_dbm, 100.0), 2);
  appendLe(bytes, fixedPoint(first_path_dbm, 100.0), 2);
  appendLe(bytes, los, 2);
  appendLe(bytes, fixedPoint(temperature_c, 10.0), 2);
  return rawTlv(static_cast<std::uint32_t>(TdoaTlvType::kQuality), bytes);
}

TdoaPacketBuilder& TdoaPacketBuilder::radio(std::uint32_t rtto, std::uint32_t integrator,
                                            std::uint8_t channel, std::uint8_t prf,
                                            std::uint8_t bitrate) {
  std::vector<std::uint8_t> bytes;
  appendLe(bytes, rtto, 3);
  appendLe(bytes, integrator, 3);
  bytes.push_back(channel);
  bytes.push_back(static_cast<std::uint8_t>((prf << 4) | (bitrate & 0x0F)));
  return rawTlv(static_cast<std::uint32_t>(TdoaTlvType::kRadio), bytes);
}

TdoaPacketBuilder& TdoaPacketBuilder::rawTlv(std::uint32_t type,
                                             const std::vector<std::uint8_t>& bytes,
                                             std::optional<std::uint32_t> length_field) {
  appendLe(tlvs_, type, 4);
  appendLe(tlvs_, length_field.value_or(static_cast<std::uint32_t>(bytes.size())), 4);
  tlvs_.insert(tlvs_.end(), bytes.begin(), bytes.end());
  ++tlv_count_;
  return *this;
}

TdoaPacketBuilder& TdoaPacketBuilder::lengthField(std::uint16_t length) {
  length_override_ = length;
  return *this;
}

TdoaPacketBuilder& TdoaPacketBuilder::tlvCountField(std::uint8_t count) {
  count_override_ = count;
  return *this;
}

std::vector<std::uint8_t> TdoaPacketBuilder::build() const {
  std::vector<std::uint8_t> out(kTdoaMagic.begin(), kTdoaMagic.end());
  appendLe(out, address_, 8);
  appendLe(out, 0x0001, 2);  // platform
  appendLe(out, 0x0100, 2);  // version
  appendLe(out, length_override_.value_or(static_cast<std::uint16_t>(tlvs_.size())), 2);
  out.push_back(sequence_);
  out.push_back(count_override_.value_or(tlv_count_));
  appendLe(out, 0, 2);  // header CRC (not verified by the decoder)
  appendLe(out, 0, 2);  // frame CRC
  out.insert(out.end(), tlvs_.begin(), tlvs_.end());
  return out;
}

}  // namespace drivers
}  // namespace radio_follow
