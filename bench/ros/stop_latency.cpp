// SPDX-License-Identifier: BSD-3-Clause
// Stop latency of a running controller: wall time from publishing a range below
// safe_distance to receiving the first zero cmd_vel, while estimates arrive at a given
// rate. Baseline in the same run: the round trip of the same message type through a
// trivial roscpp relay (this program with --echo), i.e. what two hops of transport cost.
// Run by scripts/bench_stop_latency.sh, which starts the master, the controller and the
// relay. Prints one line per measurement series: p50, p90, max (ms) and the ratio of the
// p50 to the relay's p50.
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

#include "radio_follow/TargetEstimate.h"
#include "radio_follow/UwbRanges.h"

namespace {

radio_follow::UwbRanges rangeMessage(double range) {
  radio_follow::UwbRanges r;
  r.header.stamp = ros::Time::now();
  r.tag_id = "5722";
  r.ranges.resize(1);
  r.ranges[0].anchor_id = "ABCD";
  r.ranges[0].range = range;
  return r;
}

int echo(ros::NodeHandle& nh) {
  ros::Publisher out = nh.advertise<radio_follow::UwbRanges>("echo_out", 10);
  ros::Subscriber in = nh.subscribe<radio_follow::UwbRanges>(
      "echo_in", 10, [&](const radio_follow::UwbRanges::ConstPtr& m) { out.publish(*m); },
      ros::VoidPtr(), ros::TransportHints().tcpNoDelay());
  ros::spin();
  return 0;
}

struct Series {
  std::vector<double> ms;
  void print(const char* name, double baseline_p50) {
    std::sort(ms.begin(), ms.end());
    const auto at = [&](double q) { return ms[static_cast<std::size_t>(q * (ms.size() - 1))]; };
    std::printf("%-34s n=%3zu  p50 %7.2f ms  p90 %7.2f ms  max %7.2f ms  p50/relay %5.2f\n", name,
                ms.size(), at(0.5), at(0.9), ms.back(),
                baseline_p50 > 0 ? at(0.5) / baseline_p50 : 1.0);
  }
  double p50() {
    std::sort(ms.begin(), ms.end());
    return ms[static_cast<std::size_t>(0.5 * (ms.size() - 1))];
  }
};

class Bench {
 public:
  explicit Bench(ros::NodeHandle& nh)
      : range_pub_(nh.advertise<radio_follow::UwbRanges>("uwb_ranges", 100)),
        estimate_pub_(nh.advertise<radio_follow::TargetEstimate>("target", 100)),
        echo_pub_(nh.advertise<radio_follow::UwbRanges>("echo_in", 10)),
        cmd_sub_(
            nh.subscribe("cmd_vel", 100, &Bench::onCmd, this, ros::TransportHints().tcpNoDelay())),
        echo_sub_(nh.subscribe("echo_out", 10, &Bench::onEcho, this,
                               ros::TransportHints().tcpNoDelay())) {}

  void estimates(double rate) {
    estimate_timer_ = ros::NodeHandle().createWallTimer(
        ros::WallDuration(1.0 / rate), [this](const ros::WallTimerEvent&) {
          radio_follow::TargetEstimate e;
          e.header.stamp = ros::Time::now();
          e.header.frame_id = "base_link";
          e.position.x = 4.0;
          e.range = 4.0;
          e.status = radio_follow::TargetEstimate::STATUS_OK;
          estimate_pub_.publish(e);
          if (!stopping_) {
            range_pub_.publish(rangeMessage(4.0));
          }
        });
  }

  /// One stop: wait until the robot drives, publish a short range, time the first zero.
  bool stopOnce(double& ms) {
    if (!waitUntil([&] { return moving_.load(); }, 10.0)) {
      return false;
    }
    ros::WallDuration(0.01 * (std::rand() % 10)).sleep();  // not in phase with the tick
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
      zero_seen_ = false;
      sent_ = ros::WallTime::now();
    }
    range_pub_.publish(rangeMessage(0.5));
    const bool ok = waitUntil([&] { return zero_seen_.load(); }, 2.0);
    ms = (zero_time_ - sent_).toSec() * 1e3;
    stopping_ = false;
    return ok;
  }

  bool echoOnce(double& ms) {
    echoed_ = false;
    echo_sent_ = ros::WallTime::now();
    echo_pub_.publish(rangeMessage(0.5));
    const bool ok = waitUntil([&] { return echoed_.load(); }, 2.0);
    ms = (echo_time_ - echo_sent_).toSec() * 1e3;
    return ok;
  }

 private:
  template <typename F>
  bool waitUntil(F condition, double timeout) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
    while (ros::ok() && ros::WallTime::now() < end) {
      if (condition()) {
        return true;
      }
      ros::WallDuration(0.0002).sleep();
    }
    return false;
  }

  void onCmd(const geometry_msgs::Twist::ConstPtr& msg) {
    const ros::WallTime now = ros::WallTime::now();
    moving_ = msg->linear.x > 0.05;
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_ && !zero_seen_ && msg->linear.x == 0.0) {
      zero_time_ = now;
      zero_seen_ = true;
    }
  }
  void onEcho(const radio_follow::UwbRanges::ConstPtr&) {
    echo_time_ = ros::WallTime::now();
    echoed_ = true;
  }

  ros::Publisher range_pub_;
  ros::Publisher estimate_pub_;
  ros::Publisher echo_pub_;
  ros::Subscriber cmd_sub_;
  ros::Subscriber echo_sub_;
  ros::WallTimer estimate_timer_;
  std::mutex mutex_;
  std::atomic<bool> moving_{false};
  std::atomic<bool> stopping_{false};
  std::atomic<bool> zero_seen_{false};
  std::atomic<bool> echoed_{false};
  ros::WallTime sent_, zero_time_, echo_sent_, echo_time_;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "stop_latency_bench", ros::init_options::AnonymousName);
  ros::NodeHandle nh;
  if (argc > 1 && std::strcmp(argv[1], "--echo") == 0) {
    return echo(nh);
  }
  const int trials = argc > 1 ? std::atoi(argv[1]) : 30;
  const double rate = argc > 2 ? std::atof(argv[2]) : 50.0;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  Bench bench(nh);
  bench.estimates(rate);
  ros::WallDuration(2.0).sleep();  // connections
  Series relay;
  Series stop;
  for (int i = 0; i < trials; ++i) {
    double ms = 0.0;
    if (bench.echoOnce(ms)) {
      relay.ms.push_back(ms);
    }
    if (bench.stopOnce(ms)) {
      stop.ms.push_back(ms);
    } else {
      std::fprintf(stderr, "trial %d: no stop within 2 s (or never moving)\n", i);
    }
  }
  if (relay.ms.empty() || stop.ms.empty()) {
    std::fprintf(stderr, "no measurement\n");
    return 1;
  }
  const double base = relay.p50();
  relay.print("relay round trip (baseline)", base);
  char name[64];
  std::snprintf(name, sizeof(name), "stop, estimates at %.0f Hz", rate);
  stop.print(name, base);
  return 0;
}
