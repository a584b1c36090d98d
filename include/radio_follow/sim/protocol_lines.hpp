// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace radio_follow {
namespace sim {

/// One anchor entry of a DWM1001 tag's output line.
struct DwmAnchorRange {
  std::string id;                                      ///< 4 hex digits, e.g. "DA12"
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< as configured in the anchor, m
  double range = 0.0;                                  ///< m
};

/// The tag's own position solution, when the module reports one.
struct DwmPosition {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m
  int quality = 100;                                   ///< 0-100
  std::uint32_t computation_time_us = 0;               ///< les `le_us`
};

/// A DWM1001 shell `les` line (thesis Appendix A.1), without the line ending:
/// `1151[5.00,8.00,2.25]=6.48 0CA8[0.00,8.00,2.25]=6.51 le_us=2576 est[2.57,1.98,1.68,100]`.
std::string formatLesLine(const std::vector<DwmAnchorRange>& ranges,
                          const std::optional<DwmPosition>& position);

/// A DWM1001 shell `lec` line:
/// `DIST,2,AN0,1151,5.00,8.00,2.25,6.48,AN1,0CA8,0.00,8.00,2.25,6.51,POS,2.57,1.98,1.68,100`.
std::string formatLecLine(const std::vector<DwmAnchorRange>& ranges,
                          const std::optional<DwmPosition>& position);

/// One u-blox angle-of-arrival event in the device's own conventions.
struct UudfEvent {
  std::string tag_id;     ///< 12 hex digits
  int rssi = -60;         ///< dBm
  int azimuth = 0;        ///< degrees, the device's sign (clockwise seen from above)
  int elevation = 0;      ///< degrees
  int rssi_second = -62;  ///< dBm, second polarisation
  int channel = 37;
  std::string anchor_id;     ///< quoted in the line
  std::string user_defined;  ///< quoted in the line
  std::uint32_t timestamp_ms = 0;
  std::optional<std::int64_t> event_counter;  ///< newer firmware only
};

/// A `+UUDF:` line (thesis Appendix A.2), without the line ending:
/// `+UUDF:CCF9578E0D8A,-42,20,0,-43,37,"CCF9578E0D89","",15869,23`.
std::string formatUudfLine(const UudfEvent& event);

}  // namespace sim
}  // namespace radio_follow
