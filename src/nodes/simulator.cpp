// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/common/node_main.hpp"
#include "radio_follow/ros/sim/simulator_node.hpp"

int main(int argc, char** argv) {
  return radio_follow::runNode<radio_follow::SimulatorNode>(argc, argv, "simulator");
}
