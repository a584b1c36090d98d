// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/drivers/layout_drivers.hpp"

#include "radio_follow/ros/common/node_main.hpp"

int main(int argc, char** argv) {
  return radio_follow::runNode<radio_follow::LayoutDriversNode>(argc, argv, "layout_drivers");
}
