// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace radio_follow {
namespace drivers {

/// Frequency of the DW1000 receive-timestamp counter: one tick = 1 / 63.8976 GHz = 15.65 ps.
constexpr double kTdoaTickFrequency = 63.8976e9;
/// Start of every anchor report; the reference driver (brozb/uwb_tdoa) syncs on it.
constexpr std::array<std::uint8_t, 8> kTdoaMagic{0x02, 0x01, 0x04, 0x03, 0x06, 0x05, 0x08, 0x07};
/// Magic (8) + address (8) + platform (2) + version (2) + length (2) + sequence (1)
/// + TLV count (1) + header CRC (2) + frame CRC (2).
constexpr std::size_t kTdoaHeaderSize = 28;
/// Type (4, of which the low two bytes are used) + length (4).
constexpr std::size_t kTdoaTlvHeaderSize = 8;

/// TLV types of an anchor report (doc/tdoa_protocol.md).
enum class TdoaTlvType : std::uint16_t {
  kMac = 1,        ///< MAC header of the received blink; carries the tag's short ID.
  kPayload = 2,    ///< Blink payload bytes (not used for TDoA).
  kTimestamp = 3,  ///< Receive time and its variance, ticks.
  kQuality = 4,    ///< RSSI, first-path power, LOS indicator, temperature.
  kRadio = 5,      ///< Clock offset (RTTO), integrator, channel, PRF and bit rate.
};

/// Why a datagram was not turned into a report. Order matters: it indexes counters.
enum class TdoaDecodeError : std::uint8_t {
  kOk = 0,
  kNoMagic,             ///< The magic does not occur in the datagram.
  kTooShort,            ///< Fewer than a header's bytes after the magic.
  kLengthBeyondPacket,  ///< The header's length field claims more bytes than arrived.
  kTlvTruncated,        ///< A TLV header does not fit in the length the header declares.
  kTlvOverrun,          ///< A TLV's length runs past the declared length.
  kTlvTooShort,     ///< A known TLV is shorter than its fixed fields, or a MAC is not 5..16 bytes.
  kLengthMismatch,  ///< Bytes are left over after the declared TLV count.
  kImplausible,     ///< Decodes, but the quality TLV's RSSI or first-path power is outside
                    ///< [-127, 0] dBm (plausibility.hpp): a corrupted or faulty report.
  kCount,
};

/// Number of TdoaDecodeError values (for counter arrays).
constexpr std::size_t kTdoaDecodeErrorCount = static_cast<std::size_t>(TdoaDecodeError::kCount);

/// Short name of an error, used as a diagnostics key, e.g. "tlv_overrun".
const char* toString(TdoaDecodeError error);

/// One anchor's report of one received frame, decoded from a datagram.
struct TdoaReport {
  // Header.
  std::uint64_t anchor_address = 0;  ///< The reporting anchor's 64-bit address.
  std::uint16_t platform = 0;
  std::uint16_t version = 0;
  std::uint16_t length = 0;   ///< Bytes of TLVs following the header.
  std::uint8_t sequence = 0;  ///< Sequence number of the received blink.
  std::uint8_t tlv_count = 0;
  std::uint16_t header_crc = 0;  ///< As sent; not verified (the algorithm is undocumented).
  std::uint16_t frame_crc = 0;   ///< As sent; not verified.

  // TLV 1.
  bool has_tag = false;
  std::uint16_t tag = 0;  ///< Tag short ID (bytes [n-4], [n-5] of the n-byte MAC TLV).

  // TLV 2.
  std::size_t payload_offset = 0;  ///< Offset of the payload bytes in the datagram.
  std::size_t payload_size = 0;

  // TLV 3.
  bool has_timestamp = false;
  std::uint64_t rx_ticks = 0;     ///< Receive time, ticks of 1/kTdoaTickFrequency.
  std::uint64_t rx_variance = 0;  ///< As sent (unit undocumented; not used for TDoA).

  // TLV 4.
  bool has_quality = false;
  double rssi_dbm = 0.0;
  double first_path_dbm = 0.0;
  std::uint16_t los_indicator = 0;
  double temperature_c = 0.0;

  // TLV 5.
  bool has_radio = false;
  std::uint32_t rtto = 0;        ///< 24-bit receiver time tracking offset, raw.
  std::uint32_t integrator = 0;  ///< 24-bit receiver time tracking integrator, raw.
  std::uint8_t channel = 0;
  std::uint8_t prf = 0;      ///< High nibble of the PRF/bit-rate byte.
  std::uint8_t bitrate = 0;  ///< Low nibble of the PRF/bit-rate byte.

  /// TLVs of a type other than 1..5, skipped by their length field.
  std::uint16_t unknown_tlvs = 0;
};

/// Decodes one UDP datagram. Pure: reads only [data, data + size), never past it, and
/// writes `*report` (reset first) only. Bytes before the first magic are skipped, as the
/// reference driver does; bytes after the declared length are ignored.
TdoaDecodeError decodeTdoaPacket(const std::uint8_t* data, std::size_t size, TdoaReport* report);

/// Tag short ID as four upper-case hex digits, e.g. "0CA8" (TdoaMeasurements.tag_id).
std::string tdoaTagIdString(std::uint16_t tag);

/// Anchor address as 16 upper-case hex digits.
std::string tdoaAddressString(std::uint64_t address);

}  // namespace drivers
}  // namespace radio_follow
