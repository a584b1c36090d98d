// SPDX-License-Identifier: BSD-3-Clause
// The ROS nodes' own parameter tables (wiring, the simulator, the TDoA driver, the
// announcer, the evaluator) against their commented config/*.yaml and doc pages: every
// default is declared once, in the table, and the files are checked copies of it. The
// core's tables: test/unit/common/param_tables_test.cpp.
#include <gtest/gtest.h>

#include "../../support/param_coverage.hpp"
#include "radio_follow/ros/common/layout_publisher.hpp"
#include "radio_follow/ros/control/announcer.hpp"
#include "radio_follow/ros/control/controller_base.hpp"
#include "radio_follow/ros/control/estimate_follower.hpp"
#include "radio_follow/ros/control/homing_controller.hpp"
#include "radio_follow/ros/control/path_follower.hpp"
#include "radio_follow/ros/drivers/layout_drivers.hpp"
#include "radio_follow/ros/drivers/tdoa_driver.hpp"
#include "radio_follow/ros/locator/locator_node.hpp"
#include "radio_follow/ros/sim/follow_evaluator_node.hpp"
#include "radio_follow/ros/sim/simulator_node.hpp"

namespace radio_follow {
namespace {

TEST(NodeParamTables, SimulatorIsInItsYaml) {
  // The launch files give the layout and the scenario; the page points to the YAML.
  expectCovered(SimulatorNode::Params::table(), {"simulator.yaml"}, "",
                {"layout_file", "scenario_file"});
}

TEST(NodeParamTables, FollowEvaluatorIsInItsDoc) {
  expectCovered(FollowEvaluatorNode::Params::table(), {}, "simulator.md");
}

TEST(NodeParamTables, TdoaDriverIsInItsYamlAndDoc) {
  // The clock master is the user's own anchor: the example names one, the node has none.
  expectCovered(TdoaDriverNode::Params::table(), {"tdoa_driver.yaml"}, "nodes/tdoa_driver.md",
                {"master"});
}

TEST(NodeParamTables, AnnouncerIsInItsYamlAndDoc) {
  expectCovered(AnnouncerNode::Params::table(), {"announcer.yaml"}, "nodes/announcer.md");
}

TEST(NodeParamTables, LayoutDriversIsInItsDoc) {
  expectCovered(LayoutDriversNode::Params::table(), {}, "nodes/layout_drivers.md");
}

TEST(NodeParamTables, LayoutPublisherIsInItsDoc) {
  expectCovered(LayoutPublisherNode::Params::table(), {}, "nodes/layout_publisher.md");
}

TEST(NodeParamTables, LocatorWiringIsInItsYamlAndDoc) {
  expectCovered(LocatorNode::Params::table(), {"locator.yaml"}, "nodes/locator.md",
                {"layout_file"});
}

TEST(NodeParamTables, ControllersWiringIsInTheirYamlAndDoc) {
  expectCovered(control::ControllerWiring::table(), {"controller_common.yaml"},
                "nodes/velocity_controller.md", {"layout_file"});
}

TEST(NodeParamTables, PathFollowerWiringIsInItsYamlAndDoc) {
  expectCovered(PathFollowerNode::Params::table(), {"path_follower.yaml"},
                "nodes/path_follower.md");
}

TEST(NodeParamTables, HomingControllerWiringIsInItsYamlAndDoc) {
  expectCovered(HomingControllerNode::Params::table(), {"homing_controller.yaml"},
                "nodes/homing_controller.md");
}

}  // namespace
}  // namespace radio_follow
