// SPDX-License-Identifier: BSD-3-Clause
// Starts nodes with one bad setting each (command-line private parameters, parameter
// files, layout files) and checks that each exits 1 at once, naming the parameter. Each
// case uses its own node name, so parameters left on the server do not leak into the next.
#include <gtest/gtest.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

struct NodeRun {
  int status = -1;
  std::string output;
};

/// Runs `rosrun radio_follow <node> <args>` (at most 15 s) and collects its output.
NodeRun runNode(const std::string& node, const std::string& args) {
  static int counter = 0;
  const std::string name = "strict_" + node + "_" + std::to_string(++counter);
  const std::string command =
      "timeout 15 rosrun radio_follow " + node + " __name:=" + name + " " + args + " 2>&1";
  NodeRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    return run;
  }
  std::array<char, 512> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe) != nullptr) {
    run.output += buffer.data();
  }
  const int status = pclose(pipe);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string config(const std::string& file) {
  return ros::package::getPath("radio_follow") + "/config/" + file;
}

/// A layout file made from the shipped Spot layout with `from` replaced by `to`.
std::string brokenLayout(const std::string& from, const std::string& to) {
  std::ifstream in(config("layouts/spot.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) {
    text.replace(at, from.size(), to);
  }
  static int counter = 0;
  const std::string path = "/tmp/radio_follow_strict_layout_" + std::to_string(getpid()) + "_" +
                           std::to_string(++counter) + ".yaml";
  std::ofstream(path) << text;
  return path;
}

/// The node exited 1 and its message contains every one of `needles`.
void expectRefused(const std::string& node, const std::string& args,
                   std::initializer_list<std::string> needles) {
  const NodeRun run = runNode(node, args);
  EXPECT_EQ(run.status, 1) << node << " " << args << "\n" << run.output;
  for (const std::string& needle : needles) {
    EXPECT_NE(run.output.find(needle), std::string::npos)
        << node << " " << args << ": no '" << needle << "' in\n"
        << run.output;
  }
}

TEST(StrictParams, MisspeltParameterIsRefusedWithASuggestion) {
  expectRefused("velocity_controller", "_safe_distanse:=2.0",
                {"'~safe_distanse'", "did you mean '~safe_distance'"});
  expectRefused("locator", "_layout_file:=" + config("layouts/spot.yaml") + " _rnage_sigma:=0.1",
                {"'~rnage_sigma'", "did you mean '~range_sigma'"});
  expectRefused("dwm1001_driver", "_port:=/dev/null _baud_rate:=9600", {"'~baud_rate'"});
}

TEST(StrictParams, ALowerCaseModuleNamespaceIsRefusedWithTheOneTheLocatorUses) {
  // dwm1001_driver.launch id:=5a84 would publish on uwb/5a84/ranges, unheard.
  expectRefused("dwm1001_driver", "__ns:=/uwb/5a84 _port:=/dev/null",
                {"/uwb/5a84", "/uwb/5A84", "id:=5A84"});
}

TEST(StrictParams, WrongTypeIsRefusedNotReplacedByTheDefault) {
  expectRefused("velocity_controller", "_safe_distance:=abc", {"'~safe_distance'", "'abc'"});
  expectRefused("velocity_controller", "_rate:=fast", {"'~rate'", "'fast'"});
  expectRefused("velocity_controller", "_range_topics:=uwb/5722/ranges",
                {"'~range_topics'", "a list of strings"});
  expectRefused("locator",
                "_layout_file:=" + config("layouts/spot.yaml") + " _uwb_topics:=uwb/5722/ranges",
                {"'~uwb_topics'", "a list of strings"});
  expectRefused("velocity_controller", "_start_enabled:=1", {"'~start_enabled'", "true or false"});
}

TEST(StrictParams, SafetyValuesHavePhysicalBounds) {
  expectRefused("velocity_controller", "_safe_distance:=0.0", {"'~safe_distance'"});
  expectRefused("velocity_controller", "_estimate_timeout:=1e9", {"'~estimate_timeout'"});
  expectRefused("velocity_controller", "_range_timeout:=60.0", {"'~range_timeout'"});
  // follow_distance 1.4 < safe_distance 1.3 + closing_distance 0.2.
  expectRefused("velocity_controller", "_follow_distance:=1.4",
                {"'~follow_distance'", "safe_distance + closing_distance"});
}

TEST(StrictParams, InvalidTopicNameIsAConfigurationErrorNotACrash) {
  expectRefused("velocity_controller", "'_cmd_vel_topic:=bad name'", {"'~cmd_vel_topic'"});
}

TEST(StrictParams, LayoutKeyTyposAreRefused) {
  const std::string twr = brokenLayout("twr_modules:", "twr_module:");
  expectRefused("velocity_controller", "_layout_file:=" + twr,
                {"'twr_module'", "did you mean 'twr_modules'"});
  expectRefused("locator", "_layout_file:=" + twr, {"'twr_module'"});
  const std::string calibration = brokenLayout("calibration:", "calibraton:");
  expectRefused("locator", "_layout_file:=" + calibration,
                {"'twr_modules[0].calibraton'", "did you mean 'twr_modules[0].calibration'"});
}

TEST(StrictParams, LayoutPathErrorsSayWhatToDo) {
  // Nodes run in ROS_HOME: a relative path or a `~` there is the user's most likely slip.
  expectRefused("locator", "_layout_file:=my_robot.yaml",
                {"'~layout_file'", "relative path", "absolute path"});
  expectRefused("layout_publisher", "'_layout_file:=~/my_robot.yaml'",
                {"'~layout_file'", "'~' is not expanded"});
  expectRefused("layout_drivers", "_layout_file:=/nonexistent/my_robot.yaml",
                {"'~layout_file'", "there is no file /nonexistent/my_robot.yaml"});
}

TEST(StrictParams, LayoutDriversTakeEveryDevicesIdentityFromTheLayout) {
  const std::string layout = "_layout_file:=" + config("layouts/small_kit.yaml");
  expectRefused("layout_drivers", layout + " _dwm1001/port:=/dev/ttyACM0",
                {"'~dwm1001/port'", "from the layout"});
  expectRefused("layout_drivers", layout + " _ublox_aoa/frame_id:=board",
                {"'~ublox_aoa/frame_id'", "from the layout"});
  expectRefused("layout_drivers", layout + " _dwm1001/baud_rate:=9600",
                {"'~dwm1001/baud_rate'", "a known key"});
  expectRefused("layout_drivers", layout + " _ublox_aoa/tag_ids:=[1234]", {"'~ublox_aoa/tag_ids'"});
}

TEST(StrictParams, ShippedFilesAreAccepted) {
  // The same mechanism must accept what the package ships: the node runs until killed.
  const NodeRun run =
      runNode("velocity_controller", "_layout_file:=" + config("layouts/spot.yaml") + " _rate:=20");
  EXPECT_EQ(run.status, 124) << run.output;  // still running when `timeout` ended it
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "strict_params_test");
  return RUN_ALL_TESTS();
}
