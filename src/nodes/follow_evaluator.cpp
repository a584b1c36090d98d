// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/sim/follow_evaluator_node.hpp"
#include "radio_follow/ros/common/node_main.hpp"

int main(int argc, char** argv) {
  return radio_follow::runNode<radio_follow::FollowEvaluatorNode>(argc, argv, "follow_evaluator");
}
