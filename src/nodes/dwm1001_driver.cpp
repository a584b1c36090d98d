// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/drivers/dwm1001_driver.hpp"

#include "radio_follow/ros/common/node_main.hpp"

int main(int argc, char** argv) {
  return radio_follow::runNode<radio_follow::Dwm1001DriverNode>(argc, argv, "dwm1001_driver");
}
