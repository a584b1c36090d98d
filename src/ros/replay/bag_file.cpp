// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/replay/bag_file.hpp"

#include <stdexcept>

namespace radio_follow {

void openBagForReading(rosbag::Bag& bag, const std::string& path) {
  try {
    bag.open(path, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& e) {
    throw std::runtime_error("cannot read bag '" + path + "': " + e.what());
  }
}

}  // namespace radio_follow
