// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/protocol_lines.hpp"

#include <cstdio>
#include <string>

namespace radio_follow {
namespace sim {
namespace {

/// The shell prints metres with two decimals.
std::string fixed2(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.2f", value);
  return buffer;
}

std::string triple(const Eigen::Vector3d& v, const char* separator) {
  return fixed2(v.x()) + separator + fixed2(v.y()) + separator + fixed2(v.z());
}

}  // namespace

std::string formatLesLine(const std::vector<DwmAnchorRange>& ranges,
                          const std::optional<DwmPosition>& position) {
  std::string line;
  for (const auto& r : ranges) {
    if (!line.empty()) {
      line += ' ';
    }
    line += r.id + "[" + triple(r.position, ",") + "]=" + fixed2(r.range);
  }
  if (position) {
    line += " le_us=" + std::to_string(position->computation_time_us) + " est[" +
            triple(position->position, ",") + "," + std::to_string(position->quality) + "]";
  }
  return line;
}

std::string formatLecLine(const std::vector<DwmAnchorRange>& ranges,
                          const std::optional<DwmPosition>& position) {
  std::string line = "DIST," + std::to_string(ranges.size());
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    line += ",AN" + std::to_string(i) + "," + ranges[i].id + "," + triple(ranges[i].position, ",") +
            "," + fixed2(ranges[i].range);
  }
  if (position) {
    line += ",POS," + triple(position->position, ",") + "," + std::to_string(position->quality);
  }
  return line;
}

std::string formatUudfLine(const UudfEvent& e) {
  std::string line = "+UUDF:" + e.tag_id + "," + std::to_string(e.rssi) + "," +
                     std::to_string(e.azimuth) + "," + std::to_string(e.elevation) + "," +
                     std::to_string(e.rssi_second) + "," + std::to_string(e.channel) + ",\"" +
                     e.anchor_id + "\",\"" + e.user_defined + "\"," +
                     std::to_string(e.timestamp_ms);
  if (e.event_counter) {
    line += "," + std::to_string(*e.event_counter);
  }
  return line;
}

}  // namespace sim
}  // namespace radio_follow
