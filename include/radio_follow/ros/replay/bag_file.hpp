// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <rosbag/bag.h>

#include <string>

namespace radio_follow {

/// Opens `bag` at `path` for reading; throws std::runtime_error naming the file (rosbag's
/// own exception does not say which bag it could not read).
void openBagForReading(rosbag::Bag& bag, const std::string& path);

}  // namespace radio_follow
