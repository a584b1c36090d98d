// SPDX-License-Identifier: BSD-3-Clause
// A velocity_controller that is driving is killed by a fatal signal: its last words are a
// zero cmd_vel, sent before it dies, and roslaunch's respawn brings it back disabled
// (issue 34). The terminate path (an uncaught exception) is the same handler, tested in
// test/unit/common/fatal_handlers_test.cpp.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>
#include <sys/types.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <atomic>
#include <csignal>
#include <string>
#include <thread>

#include "controller_test_utils.hpp"

namespace {

using radio_follow::FollowerStatus;
using radio_follow_test::isZero;
using radio_follow_test::waitFor;

constexpr char kNode[] = "/velocity_controller";

/// The pid of a node by its name (master lookupNode, then the node's getPid); 0 when it
/// is not registered or does not answer.
int pidOf(const std::string& node) {
  XmlRpc::XmlRpcValue args;
  XmlRpc::XmlRpcValue result;
  XmlRpc::XmlRpcValue payload;
  args[0] = ros::this_node::getName();
  args[1] = node;
  if (!ros::master::execute("lookupNode", args, result, payload, false)) {
    return 0;
  }
  const std::string uri = payload;
  const std::size_t host_begin = uri.find("://") + 3;
  const std::size_t colon = uri.find(':', host_begin);
  const std::size_t slash = uri.find('/', colon);
  XmlRpc::XmlRpcClient client(uri.substr(host_begin, colon - host_begin).c_str(),
                              std::stoi(uri.substr(colon + 1, slash - colon - 1)), "/");
  XmlRpc::XmlRpcValue pid_args;
  XmlRpc::XmlRpcValue pid_result;
  pid_args[0] = ros::this_node::getName();
  if (!client.execute("getPid", pid_args, pid_result) ||
      pid_result.getType() != XmlRpc::XmlRpcValue::TypeArray ||
      static_cast<int>(pid_result[0]) != 1) {
    return 0;
  }
  return static_cast<int>(pid_result[2]);
}

/// A far target, estimate and raw range at 4 m, at 20 Hz.
class Feeder {
 public:
  explicit Feeder(ros::NodeHandle& nh)
      : estimate_pub_(nh.advertise<radio_follow::TargetEstimate>("target", 10)),
        range_pub_(nh.advertise<radio_follow::UwbRanges>("uwb_ranges", 10)),
        timer_(nh.createWallTimer(ros::WallDuration(0.05), &Feeder::tick, this)) {}

 private:
  void tick(const ros::WallTimerEvent&) {
    const ros::Time now = ros::Time::now();
    estimate_pub_.publish(radio_follow_test::aheadEstimate(now));
    range_pub_.publish(radio_follow_test::anchorRange(now));
  }

  ros::Publisher estimate_pub_;
  ros::Publisher range_pub_;
  ros::WallTimer timer_;
};

bool enable() {
  std_srvs::SetBool srv;
  srv.request.data = true;
  return ros::service::waitForService("velocity_controller/set_enabled", ros::Duration(30.0)) &&
         ros::service::call("velocity_controller/set_enabled", srv) && srv.response.success;
}

// Dies by each fatal signal in turn while driving: the last command on the wire is zero,
// sent by the dying node itself (the respawn waits 3 s), and the new instance stays
// disabled until it is enabled again.
TEST(ControllerCrash, DyingControllerSendsZeroAndComesBackDisabled) {
  ros::NodeHandle nh;
  radio_follow_test::ControllerRecorder recorder(nh, "velocity_controller/status");
  Feeder feeder(nh);
  ASSERT_TRUE(waitFor([&] { return recorder.lastCmd().linear.x > 0.2; }, 30.0))
      << "the controller never drove toward a far target";
  for (const int signal : {SIGSEGV, SIGABRT}) {
    const int pid = pidOf(kNode);
    ASSERT_GT(pid, 0);
    ASSERT_GT(recorder.lastCmd().linear.x, 0.2);
    const ros::WallTime killed = ros::WallTime::now();
    ASSERT_EQ(kill(pid, signal), 0);
    // The zero comes from the dying node: within 1.5 s, long before the respawn (3 s).
    ASSERT_TRUE(waitFor([&] { return isZero(recorder.lastCmd()); }, 1.5))
        << "signal " << signal << ": the last command is still " << recorder.lastCmd().linear.x;
    EXPECT_LT((ros::WallTime::now() - killed).toSec(), 2.5);
    // Respawned, it comes back disabled although start_enabled is true and the inputs
    // are good, and says so.
    ASSERT_TRUE(waitFor(
        [&] {
          const int now = pidOf(kNode);
          return now > 0 && now != pid;
        },
        60.0))
        << "not respawned";
    ASSERT_TRUE(waitFor(
        [&] {
          return recorder.hasStatus() &&
                 recorder.lastStatus().state == FollowerStatus::STATE_DISABLED;
        },
        30.0));
    const int mark = recorder.cmdCount();
    ros::WallDuration(2.0).sleep();
    const auto cmds = recorder.cmdsSince(mark);
    ASSERT_FALSE(cmds.empty()) << "the respawned controller publishes nothing";
    for (const auto& cmd : cmds) {
      ASSERT_TRUE(isZero(cmd)) << "the respawned controller drives without being enabled";
    }
    ASSERT_TRUE(enable());
    ASSERT_TRUE(waitFor([&] { return recorder.lastCmd().linear.x > 0.2; }, 30.0))
        << "enabled again, it does not follow";
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "controller_crash_rostest");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
