// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/common/layout_publisher.hpp"

#include "radio_follow/ros/common/node_main.hpp"

int main(int argc, char** argv) {
  return radio_follow::runNode<radio_follow::LayoutPublisherNode>(argc, argv, "layout_publisher");
}
