// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/tdoa_packet.hpp"

#include <algorithm>
#include <cstdio>

#include "radio_follow/common/plausibility.hpp"

namespace radio_follow {
namespace drivers {
namespace {

// Explicit little-endian reads: wire bytes are never reinterpreted in place, so the
// decoder is independent of host endianness and alignment.
std::uint64_t readLe(const std::uint8_t* p, std::size_t n) {
  std::uint64_t value = 0;
  for (std::size_t i = n; i > 0; --i) {
    value = (value << 8) | p[i - 1];
  }
  return value;
}

std::uint16_t readU16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(readLe(p, 2));
}

// Fixed field sizes of the TLVs whose contents are decoded.
constexpr std::size_t kTimestampTlvSize = 16;
constexpr std::size_t kQualityTlvSize = 8;
constexpr std::size_t kRadioTlvSize = 8;
constexpr std::size_t kMinMacTlvSize = 5;
constexpr std::size_t kMaxMacTlvSize = 16;

TdoaDecodeError decodeTlv(std::uint16_t type, const std::uint8_t* p, std::size_t n,
                          std::size_t offset, TdoaReport* r) {
  switch (static_cast<TdoaTlvType>(type)) {
    case TdoaTlvType::kMac:
      if (n < kMinMacTlvSize || n > kMaxMacTlvSize) {
        return TdoaDecodeError::kTlvTooShort;
      }
      // The reference renders the MAC reversed as hex and takes characters 6..9, i.e.
      // the bytes at n-4 and n-5, most significant first.
      r->has_tag = true;
      r->tag = static_cast<std::uint16_t>((p[n - 4] << 8) | p[n - 5]);
      return TdoaDecodeError::kOk;
    case TdoaTlvType::kPayload:
      r->payload_offset = offset;
      r->payload_size = n;
      return TdoaDecodeError::kOk;
    case TdoaTlvType::kTimestamp:
      if (n < kTimestampTlvSize) {
        return TdoaDecodeError::kTlvTooShort;
      }
      r->has_timestamp = true;
      r->rx_ticks = readLe(p, 8);
      r->rx_variance = readLe(p + 8, 8);
      return TdoaDecodeError::kOk;
    case TdoaTlvType::kQuality:
      if (n < kQualityTlvSize) {
        return TdoaDecodeError::kTlvTooShort;
      }
      // Powers are signed hundredths of a dBm (two's complement), temperature tenths of
      // a degree Celsius.
      r->has_quality = true;
      r->rssi_dbm = static_cast<std::int16_t>(readU16(p)) / 100.0;
      r->first_path_dbm = static_cast<std::int16_t>(readU16(p + 2)) / 100.0;
      r->los_indicator = readU16(p + 4);
      r->temperature_c = readU16(p + 6) / 10.0;
      return TdoaDecodeError::kOk;
    case TdoaTlvType::kRadio:
      if (n < kRadioTlvSize) {
        return TdoaDecodeError::kTlvTooShort;
      }
      r->has_radio = true;
      r->rtto = static_cast<std::uint32_t>(readLe(p, 3));
      r->integrator = static_cast<std::uint32_t>(readLe(p + 3, 3));
      r->channel = p[6];
      r->prf = static_cast<std::uint8_t>(p[7] >> 4);
      r->bitrate = static_cast<std::uint8_t>(p[7] & 0x0F);
      return TdoaDecodeError::kOk;
  }
  // Unknown types are skipped by their length field, as the reference does.
  ++r->unknown_tlvs;
  return TdoaDecodeError::kOk;
}

}  // namespace

const char* toString(TdoaDecodeError error) {
  switch (error) {
    case TdoaDecodeError::kOk:
      return "ok";
    case TdoaDecodeError::kNoMagic:
      return "no_magic";
    case TdoaDecodeError::kTooShort:
      return "too_short";
    case TdoaDecodeError::kLengthBeyondPacket:
      return "length_beyond_packet";
    case TdoaDecodeError::kTlvTruncated:
      return "tlv_truncated";
    case TdoaDecodeError::kTlvOverrun:
      return "tlv_overrun";
    case TdoaDecodeError::kTlvTooShort:
      return "tlv_too_short";
    case TdoaDecodeError::kLengthMismatch:
      return "length_mismatch";
    case TdoaDecodeError::kImplausible:
      return "implausible_value";
    case TdoaDecodeError::kCount:
      break;
  }
  return "unknown";
}

TdoaDecodeError decodeTdoaPacket(const std::uint8_t* data, std::size_t size, TdoaReport* report) {
  *report = TdoaReport{};
  const std::uint8_t* end = data + size;
  const std::uint8_t* start = std::search(data, end, kTdoaMagic.begin(), kTdoaMagic.end());
  if (start == end) {
    return TdoaDecodeError::kNoMagic;
  }
  const auto available = static_cast<std::size_t>(end - start);
  if (available < kTdoaHeaderSize) {
    return TdoaDecodeError::kTooShort;
  }
  const std::uint8_t* h = start + kTdoaMagic.size();
  TdoaReport& r = *report;
  r.anchor_address = readLe(h, 8);
  r.platform = readU16(h + 8);
  r.version = readU16(h + 10);
  r.length = readU16(h + 12);
  r.sequence = h[14];
  r.tlv_count = h[15];
  r.header_crc = readU16(h + 16);
  r.frame_crc = readU16(h + 18);
  if (r.length > available - kTdoaHeaderSize) {
    return TdoaDecodeError::kLengthBeyondPacket;
  }

  // Every bound below is against the declared TLV area, which is known to lie inside
  // the datagram; `remaining` never underflows because each step checks before it takes.
  const std::uint8_t* p = start + kTdoaHeaderSize;
  std::size_t remaining = r.length;
  for (unsigned i = 0; i < r.tlv_count; ++i) {
    if (remaining < kTdoaTlvHeaderSize) {
      return TdoaDecodeError::kTlvTruncated;
    }
    const std::uint16_t type = readU16(p);  // bytes 2..3 of the type field are ignored
    const std::uint64_t tlv_length = readLe(p + 4, 4);
    p += kTdoaTlvHeaderSize;
    remaining -= kTdoaTlvHeaderSize;
    if (tlv_length > remaining) {
      return TdoaDecodeError::kTlvOverrun;
    }
    const auto n = static_cast<std::size_t>(tlv_length);
    const TdoaDecodeError error = decodeTlv(type, p, n, static_cast<std::size_t>(p - data), &r);
    if (error != TdoaDecodeError::kOk) {
      return error;
    }
    p += n;
    remaining -= n;
  }
  if (remaining != 0) {
    return TdoaDecodeError::kLengthMismatch;
  }
  // Values are judged once the structure is known to be whole.
  if (r.has_quality && !(plausibleRssi(r.rssi_dbm) && plausibleRssi(r.first_path_dbm))) {
    return TdoaDecodeError::kImplausible;
  }
  return TdoaDecodeError::kOk;
}

std::string tdoaTagIdString(std::uint16_t tag) {
  char text[5];
  std::snprintf(text, sizeof(text), "%04X", static_cast<unsigned>(tag));
  return text;
}

std::string tdoaAddressString(std::uint64_t address) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016llX", static_cast<unsigned long long>(address));
  return text;
}

}  // namespace drivers
}  // namespace radio_follow
