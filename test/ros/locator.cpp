// SPDX-License-Identifier: BSD-3-Clause
// Feeds driver-style messages to a running locator (Spot layout) and checks the published
// estimate, pose, TF, markers and path, the diagnostics and the warning about an input
// that never publishes, and that the target is reported lost when they stop.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <thread>

#include "controller_test_utils.hpp"
#include "radio_follow/AoaBearing.h"
#include "radio_follow/TargetEstimate.h"
#include "radio_follow/UwbRanges.h"
#include "radio_follow/config/layout.hpp"

namespace {

std::string lower(std::string s) {
  for (char& c : s) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return s;
}

// The person stands 4 m ahead, 1 m to the left, tag at the configured 1.0 m height.
const Eigen::Vector3d kTruth(4.0, 1.0, 1.0);
std::atomic<bool> g_publishing{true};
std::atomic<bool> g_running{true};
std::atomic<double> g_stamp_offset{0.0};  // s added to every stamp: a clock ahead

/// The raw reading a module reports for a true range: the inverse of the layout's linear
/// calibration (the drivers report raw ranges; the locator calibrates them).
double rawRange(const radio_follow::TwrModule& module, double range) {
  const std::vector<double>& c = module.calibration;
  return c.size() >= 2 ? (range - c[0]) / c[1] : range;
}

// Plays three UWB modules and two AoA boards at 20 Hz: "front" sees the tag, "back" hears
// a reflection every fourth cycle (five times a real board's reflection share, issue 35)
// and reports a plausible bearing inside its own field of view. (A board whose every
// reading is one steady reflection, 48 deg from what the other sees, is not told from it:
// with real boards' correlated errors each counts for a half-second's worth of readings,
// and Spot's estimate moves to the mirror image that both explain half-way.)
void playDrivers() {
  ros::NodeHandle nh;
  ros::Publisher uwb = nh.advertise<radio_follow::UwbRanges>("uwb/ranges", 10);
  ros::Publisher front = nh.advertise<radio_follow::AoaBearing>("aoa/front/bearing", 10);
  ros::Publisher back = nh.advertise<radio_follow::AoaBearing>("aoa/back/bearing", 10);
  std::string layout_file;
  ros::param::get("/locator/layout_file", layout_file);
  const radio_follow::Layout layout = radio_follow::loadLayoutFile(layout_file);
  const Eigen::Vector3d front_board(0.065, 0.0, 0.25);
  ros::Rate rate(20.0);
  std::uint64_t cycle = 0;
  while (ros::ok() && g_running) {
    if (!g_publishing) {
      rate.sleep();
      continue;
    }
    const ros::Time now = ros::Time::now() + ros::Duration(g_stamp_offset.load());
    for (const auto& m : layout.twr_modules) {
      radio_follow::UwbRanges msg;
      msg.header.stamp = now;
      msg.header.frame_id = m.frame_id;
      // In lower case, as a bag or another driver may write them: IDs are normalised
      // where they enter, so "5a84"/"da12" must match the layout's "5A84"/"DA12".
      msg.tag_id = lower(m.id);
      radio_follow::UwbRange target;
      target.anchor_id = lower(layout.target_anchor_id);
      target.range = rawRange(m, (kTruth - m.position).norm());
      radio_follow::UwbRange other;  // another anchor of the network: must be ignored
      other.anchor_id = "0B0B";
      other.range = 0.7;
      msg.ranges = {other, target};
      uwb.publish(msg);
    }
    radio_follow::AoaBearing f;
    f.header.stamp = now;
    f.header.frame_id = "aoa_front";
    const Eigen::Vector3d v = kTruth - front_board;
    f.azimuth = std::atan2(v.y(), v.x());
    f.elevation = std::atan2(v.z(), v.head<2>().norm());
    f.rssi = -58.0;
    front.publish(f);
    radio_follow::AoaBearing b = f;
    b.header.frame_id = "aoa_back";
    b.azimuth = 0.6;  // would pull the estimate to the robot's rear left
    b.elevation = 0.1;
    b.rssi = -52.0;  // and it is the louder one
    if (++cycle % 4 == 0) {
      back.publish(b);
    }
    rate.sleep();
  }
}

radio_follow::TargetEstimateConstPtr waitForStatus(std::uint8_t status, double timeout) {
  ros::NodeHandle nh;
  const ros::Time deadline = ros::Time::now() + ros::Duration(timeout);
  while (ros::ok() && ros::Time::now() < deadline) {
    auto msg =
        ros::topic::waitForMessage<radio_follow::TargetEstimate>("target", nh, ros::Duration(1.0));
    if (msg && msg->status == status) {
      return msg;
    }
  }
  return nullptr;
}

/// Every estimate the locator publishes while it lives, in arrival order.
class EstimateLog {
 public:
  EstimateLog() {
    sub_ = nh_.subscribe<radio_follow::TargetEstimate>(
        "target", 100, [this](const radio_follow::TargetEstimate::ConstPtr& msg) {
          const std::lock_guard<std::mutex> lock(mutex_);
          log_.push_back(msg);
        });
  }
  std::vector<radio_follow::TargetEstimateConstPtr> get() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return log_;
  }

 private:
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
  mutable std::mutex mutex_;
  std::vector<radio_follow::TargetEstimateConstPtr> log_;
};

/// Whether one of `log`'s estimates has this stamp and this position (the same numbers).
bool published(const std::vector<radio_follow::TargetEstimateConstPtr>& log, const ros::Time& stamp,
               double x, double y, double z) {
  return std::any_of(log.begin(), log.end(), [&](const auto& m) {
    return m->header.stamp == stamp && m->position.x == x && m->position.y == y &&
           m->position.z == z;
  });
}

// The shipped estimator (particle filter, model sigmas of real sensors) on noise-free data.
// The back board faces away from the target and now and then reports a louder, wrong
// bearing: the particle filter does not drop the board as the solver's board selection
// does; its reflections fall in the outlier share and move the estimate by some
// centimetres, and the
// particles move each estimate by a few more (+-0.05 m): the mean of one second is
// checked against the tolerance, every estimate against its own covariance.
constexpr double kTolerance = 0.12;

TEST(Locator, EstimatesTheTargetAndIgnoresTheBoardBehind) {
  // A few epochs for the filter to settle (noise-free data: it converges to the truth).
  ASSERT_TRUE(waitForStatus(radio_follow::TargetEstimate::STATUS_OK, 30.0));
  ros::Duration(1.0).sleep();
  const EstimateLog log;
  // 15 OK estimates (0.75 s at 20 Hz), however long a loaded machine takes to deliver
  // them. One that is not OK (this node's feed stalled beyond max_age) is not judged.
  const auto ok_estimates = [&] {
    std::vector<radio_follow::TargetEstimateConstPtr> ok;
    for (const auto& msg : log.get()) {
      if (msg->status == radio_follow::TargetEstimate::STATUS_OK) {
        ok.push_back(msg);
      }
    }
    return ok;
  };
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(20.0);
  while (ok_estimates().size() < 15 && ros::WallTime::now() < give_up) {
    ros::WallDuration(0.05).sleep();
  }
  const auto estimates = ok_estimates();
  ASSERT_GE(estimates.size(), 15u);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& msg : estimates) {
    EXPECT_EQ(msg->header.frame_id, "base_link");
    const Eigen::Vector3d p(msg->position.x, msg->position.y, msg->position.z);
    sum += p;
    Eigen::Matrix2d covariance;
    covariance << msg->position_covariance[0], msg->position_covariance[1],
        msg->position_covariance[3], msg->position_covariance[4];
    const Eigen::Vector2d error = (p - kTruth).head<2>();
    EXPECT_LT(error.dot(covariance.ldlt().solve(error)), 3.0 * 3.0)
        << "error (" << error.transpose() << ") outside 3 sigma of its own covariance";
    EXPECT_NEAR(msg->position.z, kTruth.z(), 1e-9);
    EXPECT_NEAR(msg->range, p.head<2>().norm(), 1e-9);
    EXPECT_NEAR(msg->bearing, std::atan2(p.y(), p.x()), 1e-9);
    EXPECT_EQ(msg->sources,
              radio_follow::TargetEstimate::SOURCE_TWR | radio_follow::TargetEstimate::SOURCE_AOA);
    EXPECT_EQ(msg->odom_frame, "") << "no odometry TF yet: no odometry-frame part";
  }
  const Eigen::Vector3d mean = sum / static_cast<double>(estimates.size());
  EXPECT_NEAR(mean.x(), kTruth.x(), kTolerance);
  EXPECT_NEAR(mean.y(), kTruth.y(), kTolerance);
  EXPECT_NEAR(std::atan2(mean.y(), mean.x()), std::atan2(kTruth.y(), kTruth.x()), 0.03);
}

// The pose and the TF carry the estimate itself: the same stamp, the same numbers.
// Nothing here waits a fixed time: on a loaded machine (issue 34: 2 failures in 19 runs)
// the log's connection and each message may come late, so every wait polls with a bound
// (waitFor).
TEST(Locator, PublishesPoseAndTf) {
  ros::NodeHandle nh;
  const EstimateLog log;
  // Connected before the pose it is compared with: the log holds estimates.
  ASSERT_TRUE(radio_follow_test::waitFor([&] { return !log.get().empty(); }, 20.0));
  const auto pose = ros::topic::waitForMessage<geometry_msgs::PoseWithCovarianceStamped>(
      "target_pose", nh, ros::Duration(5.0));
  ASSERT_TRUE(pose);
  EXPECT_EQ(pose->header.frame_id, "base_link");

  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  std::string error;
  ASSERT_TRUE(buffer.canTransform("base_link", "target", ros::Time(0), ros::Duration(5.0), &error))
      << error;
  const auto t = buffer.lookupTransform("base_link", "target", ros::Time(0));
  const auto& p = pose->pose.pose.position;
  EXPECT_TRUE(radio_follow_test::waitFor(
      [&] { return published(log.get(), pose->header.stamp, p.x, p.y, p.z); }, 10.0))
      << "no estimate stamped " << pose->header.stamp << " at (" << p.x << ", " << p.y << ", "
      << p.z << ")";
  const auto& v = t.transform.translation;
  EXPECT_TRUE(radio_follow_test::waitFor(
      [&] { return published(log.get(), t.header.stamp, v.x, v.y, v.z); }, 10.0))
      << "no estimate stamped " << t.header.stamp << " at (" << v.x << ", " << v.y << ", " << v.z
      << ")";
  EXPECT_NEAR(v.x, kTruth.x(), 3.0 * kTolerance);  // and it is the target
  EXPECT_NEAR(v.y, kTruth.y(), 3.0 * kTolerance);
}

TEST(Locator, DrawsRangesBearingsAndTheEstimate) {
  ros::NodeHandle nh;
  const auto markers = ros::topic::waitForMessage<visualization_msgs::MarkerArray>(
      "markers", nh, ros::Duration(5.0));
  ASSERT_TRUE(markers);
  int circles = 0;
  int used_arrows = 0;
  int ignored_arrows = 0;
  int estimates = 0;
  for (const auto& m : markers->markers) {
    if (m.ns == "ranges")
      circles += m.type == visualization_msgs::Marker::LINE_STRIP;
    if (m.ns == "bearings")
      (m.color.g > 0.8f ? used_arrows : ignored_arrows)++;
    if (m.ns == "estimate") {
      ++estimates;
      EXPECT_NEAR(m.pose.position.x, kTruth.x(), kTolerance);
    }
  }
  EXPECT_EQ(circles, 3);
  EXPECT_EQ(used_arrows, 1);     // front
  EXPECT_EQ(ignored_arrows, 1);  // back: the target is outside its field of view
  EXPECT_EQ(estimates, 1);
}

TEST(Locator, PublishesTheBoundedPathOfRecentEstimates) {
  ros::NodeHandle nh;
  ros::Duration(2.0).sleep();  // > 30 estimates at 20 Hz
  const auto path =
      ros::topic::waitForMessage<nav_msgs::Path>("target_path", nh, ros::Duration(5.0));
  ASSERT_TRUE(path);
  EXPECT_EQ(path->header.frame_id, "base_link");
  EXPECT_EQ(path->poses.size(), 30u);  // ~path_length
  for (std::size_t i = 1; i < path->poses.size(); ++i) {
    EXPECT_LT(path->poses[i - 1].header.stamp, path->poses[i].header.stamp);
  }
  EXPECT_NEAR(path->poses.back().pose.position.x, kTruth.x(), 0.05);
}

TEST(Locator, DrawsTheCovarianceAsARingAboveASmallEstimate) {
  ros::NodeHandle nh;
  const auto markers = ros::topic::waitForMessage<visualization_msgs::MarkerArray>(
      "markers", nh, ros::Duration(5.0));
  ASSERT_TRUE(markers);
  const visualization_msgs::Marker* sphere = nullptr;
  const visualization_msgs::Marker* ring = nullptr;
  for (const auto& m : markers->markers) {
    sphere = m.ns == "estimate" ? &m : sphere;
    ring = m.ns == "covariance" ? &m : ring;
  }
  ASSERT_TRUE(sphere && ring);
  EXPECT_EQ(ring->type, visualization_msgs::Marker::LINE_STRIP);
  EXPECT_LE(sphere->scale.x, 0.1);
  for (const auto& p : ring->points) {
    EXPECT_GT(p.z, sphere->pose.position.z + 0.5 * sphere->scale.z);  // drawn over the sphere
  }
}

TEST(Locator, WarnsAboutTheInputThatNeverPublishesNamingItsTopic) {
  ros::NodeHandle nh;
  std::atomic<bool> warned{false};
  ros::Subscriber rosout = nh.subscribe<rosgraph_msgs::Log>(
      "/rosout", 100, [&](const rosgraph_msgs::Log::ConstPtr& msg) {
        warned = warned || (msg->name == "/locator" && msg->level == rosgraph_msgs::Log::WARN &&
                            msg->msg.find("/aoa/left/bearing") != std::string::npos);
      });
  // input_timeout 1 s, one warning per input per 10 s.
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(15.0);
  while (!warned && ros::WallTime::now() < deadline) {
    ros::WallDuration(0.1).sleep();
  }
  EXPECT_TRUE(warned) << "no WARN on /rosout naming /aoa/left/bearing within 15 s";
}

TEST(Locator, DiagnosticsNameTheSilentInputAndTheHardware) {
  ros::NodeHandle nh;
  std::atomic<bool> done{false};
  diagnostic_msgs::DiagnosticStatus locator, target;
  std::mutex mutex;
  ros::Subscriber sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
        const std::lock_guard<std::mutex> lock(mutex);
        for (const auto& s : msg->status) {
          if (s.name == "locator: locator") {
            locator = s;
          } else if (s.name == "locator: locator output /target topic status") {
            target = s;
          }
        }
        // The newest statuses, until they say what is expected: the first ones may come
        // from a stall of this node's feed (an input silent for a moment).
        std::string silent;
        for (const auto& kv : locator.values) {
          silent = kv.key == "silent inputs" ? kv.value : silent;
        }
        done = !locator.name.empty() && !target.name.empty() && silent == "/aoa/left/bearing" &&
               target.level == diagnostic_msgs::DiagnosticStatus::OK;
      });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
  while (!done && ros::WallTime::now() < deadline) {
    ros::WallDuration(0.1).sleep();
  }
  const std::lock_guard<std::mutex> lock(mutex);
  ASSERT_FALSE(locator.name.empty() || target.name.empty())
      << "no locator status and /target topic status within 20 s";
  EXPECT_EQ(locator.level, diagnostic_msgs::DiagnosticStatus::WARN);
  EXPECT_NE(locator.message.find("/aoa/left/bearing"), std::string::npos) << locator.message;
  EXPECT_EQ(locator.hardware_id, "layout spot, frame base_link");
  std::string silent;
  for (const auto& kv : locator.values) {
    silent = kv.key == "silent inputs" ? kv.value : silent;
  }
  EXPECT_EQ(silent, "/aoa/left/bearing");  // the others publish
  EXPECT_EQ(target.level, diagnostic_msgs::DiagnosticStatus::OK) << target.message;
}

// Issue 34, defect 2: one range stamped 2^32-1 s while tracking made the locator abort
// (tf2's error text for the lookup overflowed ros::Duration). It is dropped by its stamp,
// and the locator keeps tracking.
TEST(Locator, ARangeStampedAtTheEndOfTimeIsDroppedAndTrackingGoesOn) {
  ASSERT_TRUE(waitForStatus(radio_follow::TargetEstimate::STATUS_OK, 30.0));
  ros::NodeHandle nh;
  // Odometry, as on a robot: the locator places each measurement with TF at its stamp,
  // and tf2's "extrapolation into the future" text for 2^32-1 s is what overflowed.
  tf2_ros::TransformBroadcaster odometry;
  const ros::WallTimer odometry_timer =
      nh.createWallTimer(ros::WallDuration(0.02), [&](const ros::WallTimerEvent&) {
        geometry_msgs::TransformStamped t;
        t.header.stamp = ros::Time::now();
        t.header.frame_id = "odom";
        t.child_frame_id = "base_link";
        t.transform.rotation.w = 1.0;
        odometry.sendTransform(t);
      });
  ros::WallDuration(1.0).sleep();  // the locator has odometry
  ros::Publisher uwb = nh.advertise<radio_follow::UwbRanges>("uwb/ranges", 10);
  ASSERT_TRUE(radio_follow_test::waitFor([&] { return uwb.getNumSubscribers() > 0; }, 10.0));
  std::string layout_file;
  ros::param::get("/locator/layout_file", layout_file);
  const radio_follow::Layout layout = radio_follow::loadLayoutFile(layout_file);
  radio_follow::UwbRanges msg;
  msg.header.stamp = ros::Time(4294967295u, 0);
  msg.tag_id = layout.twr_modules.front().id;
  radio_follow::UwbRange r;
  r.anchor_id = layout.target_anchor_id;
  r.range = 4.0;
  msg.ranges = {r};
  for (const double range : {4.0, std::numeric_limits<double>::infinity(), 1e300, -1.0}) {
    msg.ranges[0].range = range;
    uwb.publish(msg);
  }
  ros::WallDuration(1.0).sleep();
  // Alive and still tracking: OK estimates keep coming.
  EXPECT_TRUE(waitForStatus(radio_follow::TargetEstimate::STATUS_OK, 10.0));

  // With odometry each estimate carries its odometry-frame part, the particle filter's own
  // state (odom = base_link here): the same position, a standing person's ground velocity.
  const EstimateLog log;
  ASSERT_TRUE(radio_follow_test::waitFor(
      [&] {
        const auto l = log.get();
        return std::any_of(l.begin(), l.end(), [](const auto& m) {
          return m->status == radio_follow::TargetEstimate::STATUS_OK && m->odom_frame == "odom";
        });
      },
      15.0));
  for (const auto& m : log.get()) {
    if (m->odom_frame.empty()) {
      continue;  // the track restarted in the odometry frame: no estimate from it yet
    }
    EXPECT_EQ(m->odom_frame, "odom");
    EXPECT_NEAR(m->odom_position.x, m->position.x, 1e-6);
    EXPECT_NEAR(m->odom_position.y, m->position.y, 1e-6);
    EXPECT_NEAR(m->odom_robot.x, 0.0, 1e-9);
    EXPECT_NEAR(m->odom_robot.y, 0.0, 1e-9);
    EXPECT_LT(std::hypot(m->odom_velocity.x, m->odom_velocity.y), 1.0);
  }
}

TEST(Locator, ReportsLostWhenTheDriversStop) {
  g_publishing = false;
  EXPECT_TRUE(waitForStatus(radio_follow::TargetEstimate::STATUS_LOST, 10.0));
}

// Drivers whose clock is 80 s ahead: their measurements must never make an estimate (the
// locator used to publish OK estimates with no input for as long as the stamps led).
TEST(Locator, MeasurementsFromTheFutureNeverMakeAnEstimate) {
  ros::NodeHandle nh;
  std::atomic<int> usable{0};
  std::atomic<int> received{0};
  ros::Subscriber sub = nh.subscribe<radio_follow::TargetEstimate>(
      "target", 50, [&](const radio_follow::TargetEstimate::ConstPtr& msg) {
        ++received;
        usable += msg->status != radio_follow::TargetEstimate::STATUS_LOST;
      });
  ros::WallDuration(0.5).sleep();
  g_stamp_offset = 80.0;
  g_publishing = true;
  ros::WallDuration(2.0).sleep();
  g_publishing = false;
  ros::WallDuration(2.0).sleep();
  EXPECT_GT(received.load(), 20);
  EXPECT_EQ(usable.load(), 0) << "estimates made of measurements stamped 80 s ahead";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "locator_rostest");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  std::thread drivers(playDrivers);
  const int result = RUN_ALL_TESTS();
  g_running = false;
  drivers.join();
  return result;
}
