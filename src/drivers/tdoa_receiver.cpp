// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/tdoa_receiver.hpp"

#include <cmath>
#include <numeric>
#include <utility>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace drivers {
namespace {

double checkedWindow(double window) {
  require(std::isfinite(window) && window > 0.0 && window <= 1.0, "~group_window", window,
          "a time in seconds in (0, 1]");
  return window;
}

}  // namespace

std::uint64_t TdoaStats::rejected() const {
  return std::accumulate(decode_errors.begin() + 1, decode_errors.end(), std::uint64_t{0}) +
         unknown_anchor + missing_tlv + duplicate;
}

TdoaReceiver::TdoaReceiver(TdoaDifferenceConfig config, double group_window)
    : calculator_(std::move(config)),
      grouper_(calculator_.config().anchors.size(), checkedWindow(group_window)) {}

TdoaDecodeError TdoaReceiver::onDatagram(const std::uint8_t* data, std::size_t size, double now,
                                         std::vector<TdoaBlink>* out) {
  ++stats_.packets;
  TdoaReport report;
  const TdoaDecodeError error = decodeTdoaPacket(data, size, &report);
  if (error != TdoaDecodeError::kOk) {
    ++stats_.decode_errors[static_cast<std::size_t>(error)];
    return error;
  }
  const auto& anchors = calculator_.config().anchors;
  std::size_t anchor = 0;
  while (anchor < anchors.size() && anchors[anchor].address != report.anchor_address) {
    ++anchor;
  }
  if (anchor == anchors.size()) {
    ++stats_.unknown_anchor;
    return error;
  }
  if (!report.has_tag || !report.has_timestamp) {
    ++stats_.missing_tlv;
    return error;
  }
  const auto result =
      grouper_.add(report.tag, report.sequence, {anchor, report.rx_ticks}, now, &emitted_);
  if (result == TdoaBlinkGrouper::AddResult::kDuplicate) {
    ++stats_.duplicate;
  } else {
    ++stats_.reports;
  }
  finish(out);
  return error;
}

void TdoaReceiver::onTimer(double now, std::vector<TdoaBlink>* out) {
  grouper_.expire(now, &emitted_);
  finish(out);
}

void TdoaReceiver::finish(std::vector<TdoaBlink>* out) {
  for (const auto& group : emitted_) {
    TdoaBlink blink;
    blink.tag = group.tag;
    blink.first_arrival = group.first_arrival;
    const auto outcome =
        calculator_.compute(group, &blink.differences, &stats_.implausible_differences);
    if (outcome != TdoaDifferenceCalculator::Outcome::kOk) {
      ++stats_.blinks_dropped;
      continue;
    }
    ++stats_.blinks;
    stats_.blinks_incomplete += group.complete ? 0 : 1;
    out->push_back(std::move(blink));
  }
  emitted_.clear();
}

}  // namespace drivers
}  // namespace radio_follow
