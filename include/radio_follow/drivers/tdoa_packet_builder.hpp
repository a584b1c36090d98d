// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace radio_follow {
namespace drivers {

/// Encodes anchor reports in the wire format decodeTdoaPacket() reads
/// (doc/tdoa_protocol.md). Used by tests, the fuzzer's seed corpus, the benchmark and
/// the simulator side of the rostest; it can also write deliberately broken packets.
class TdoaPacketBuilder {
 public:
  TdoaPacketBuilder(std::uint64_t anchor_address, std::uint8_t sequence);

  /// TLV 1: an 8-byte MAC whose bytes 3 and 4 carry the tag short ID.
  TdoaPacketBuilder& mac(std::uint16_t tag);
  /// TLV 2: opaque payload bytes.
  TdoaPacketBuilder& payload(const std::vector<std::uint8_t>& bytes);
  /// TLV 3: receive time and variance in ticks.
  TdoaPacketBuilder& timestamp(std::uint64_t rx_ticks, std::uint64_t variance = 0);
  /// TLV 4: powers in dBm (hundredths on the wire), LOS indicator, temperature in deg C.
  TdoaPacketBuilder& quality(double rssi_dbm, double first_path_dbm, std::uint16_t los,
                             double temperature_c);
  /// TLV 5: 24-bit RTTO and integrator, channel, PRF and bit-rate nibbles.
  TdoaPacketBuilder& radio(std::uint32_t rtto, std::uint32_t integrator, std::uint8_t channel,
                           std::uint8_t prf, std::uint8_t bitrate);
  /// Any TLV, with a length field that may disagree with the bytes (for broken packets).
  TdoaPacketBuilder& rawTlv(std::uint32_t type, const std::vector<std::uint8_t>& bytes,
                            std::optional<std::uint32_t> length_field = std::nullopt);

  /// Overrides the header's length / TLV count fields (default: the true values).
  TdoaPacketBuilder& lengthField(std::uint16_t length);
  TdoaPacketBuilder& tlvCountField(std::uint8_t count);

  /// The datagram: magic, header, TLVs.
  std::vector<std::uint8_t> build() const;

 private:
  std::uint64_t address_;
  std::uint8_t sequence_;
  std::uint8_t tlv_count_ = 0;
  std::vector<std::uint8_t> tlvs_;
  std::optional<std::uint16_t> length_override_;
  std::optional<std::uint8_t> count_override_;
};

}  // namespace drivers
}  // namespace radio_follow
