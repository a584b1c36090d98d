// SPDX-License-Identifier: BSD-3-Clause
// Issue 14's recovery from a mirror, through the node: Spot's three modules lie nearly on
// a line, so a person on one side and the image across that line give almost the same
// ranges and only the bearings tell them apart. For 3 s every bearing is a reflection
// from the image (the track settles there), then the boards see the person. After 10 epochs
// of true bearings (1 s) the published target must be on the person's side, and
// stay there; in between it is the old track or AMBIGUOUS, never somewhere else.
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../support/spin_until.hpp"
#include "../support/uwb_ranges.hpp"
#include "radio_follow/AoaBearing.h"
#include "radio_follow/TargetEstimate.h"
#include "radio_follow/UwbRanges.h"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/measurement_models.hpp"
#include "radio_follow/estimation/mirror_axis.hpp"

namespace rf = radio_follow;

namespace {

using Target = rf::TargetEstimate;

/// The raw reading a module reports for a true range: the inverse of the layout's linear
/// calibration (the drivers report raw ranges; the locator calibrates them).
double rawRange(const rf::TwrModule& module, double range) {
  const std::vector<double>& c = module.calibration;
  return c.size() >= 2 ? (range - c[0]) / c[1] : range;
}

struct Seen {
  double stamp;
  std::uint8_t status;
  Eigen::Vector2d position;
};

TEST(LocatorMirror, LeavesTheMirrorWithinOneSecondOfTheFirstTrueBearing) {
  ros::NodeHandle nh;
  std::string layout_file;
  ASSERT_TRUE(ros::param::get("/locator/layout_file", layout_file));
  const rf::Layout layout = rf::loadLayoutFile(layout_file);
  double height = 0.0;
  ASSERT_TRUE(ros::param::get("/locator/target_height", height));

  // The person 2.6 m out on the left front; the image across the modules' axis.
  std::vector<Eigen::Vector3d> modules;
  for (const rf::TwrModule& m : layout.twr_modules) {
    modules.push_back(m.position);
  }
  const auto axis = rf::estimation::mirrorAxis(modules);
  ASSERT_TRUE(axis);
  const Eigen::Vector3d truth(1.0, 2.5, height);
  const Eigen::Vector3d image = axis->reflect(truth);
  ASSERT_GT((truth - image).head<2>().norm(), 4.0);
  const auto onTruthSide = [&](const Eigen::Vector2d& p) {
    return axis->leftOf({p.x(), p.y(), 0.0}) == axis->leftOf(truth);
  };

  std::vector<ros::Publisher> ranges, bearings;
  for (const rf::TwrModule& m : layout.twr_modules) {
    ranges.push_back(nh.advertise<rf::UwbRanges>("uwb/" + m.id + "/ranges", 10));
  }
  for (const rf::AoaBoard& b : layout.aoa_boards) {
    bearings.push_back(nh.advertise<rf::AoaBearing>("aoa/" + b.id + "/bearing", 10));
  }
  std::vector<Seen> seen;
  ros::Subscriber sub = nh.subscribe<Target>("target", 100, [&](const Target::ConstPtr& m) {
    seen.push_back({m->header.stamp.toSec(), m->status, {m->position.x, m->position.y}});
  });
  ASSERT_TRUE(rf::test::spinUntil([&] {
    for (const auto* list : {&ranges, &bearings}) {
      for (const ros::Publisher& p : *list) {
        if (p.getNumSubscribers() == 0) {
          return false;
        }
      }
    }
    return sub.getNumPublishers() > 0;
  })) << "the locator did not connect";

  // 10 Hz epochs: every module's range to the person; every board that has `source` in
  // front of it reports its direction (the image's first: reflections, then the person's).
  const auto epoch = [&](const Eigen::Vector3d& source) {
    const ros::Time now = ros::Time::now();
    for (std::size_t i = 0; i < layout.twr_modules.size(); ++i) {
      const rf::TwrModule& m = layout.twr_modules[i];
      ranges[i].publish(rf::test::uwbRanges(m, layout.target_anchor_id,
                                            rawRange(m, (truth - m.position).norm()), now));
    }
    for (std::size_t i = 0; i < layout.aoa_boards.size(); ++i) {
      const rf::AoaBoard& b = layout.aoa_boards[i];
      if ((b.orientation.conjugate() * (source - b.position)).x() <= 0.0) {
        continue;  // behind the board
      }
      const Eigen::Vector2d ae =
          rf::estimation::predictBearing(source, b.position, b.orientation.toRotationMatrix());
      rf::AoaBearing msg;
      msg.header.stamp = now;
      msg.header.frame_id = b.frame_id;
      msg.azimuth = ae(0);
      msg.elevation = ae(1);
      msg.rssi = -60.0;
      bearings[i].publish(msg);
    }
    return now.toSec();
  };
  ros::Rate rate(10.0);
  for (int k = 0; k < 30; ++k) {
    epoch(image);
    ros::spinOnce();
    rate.sleep();
  }
  const double switched = epoch(truth);  // the first true bearing's stamp
  rate.sleep();
  // The recovery is due after 10 epochs of true bearings (1 s at 10 Hz): from the 11th
  // epoch's stamp on. A stall of this node delays epochs; it does not make them fewer.
  double due = switched;
  for (int k = 1; k < 30; ++k) {
    const double stamp = epoch(truth);
    due = k == 10 ? stamp : due;
    ros::spinOnce();
    rate.sleep();
  }
  rf::test::spinUntil([&] { return false; }, 0.3);  // the last estimates

  // The reflections did move the track to the image, or this test proves nothing.
  const Seen* last_before = nullptr;
  for (const Seen& s : seen) {
    if (s.stamp < switched && rf::TargetEstimate::STATUS_LOST != s.status) {
      last_before = &s;
    }
  }
  ASSERT_NE(last_before, nullptr) << "no estimate before the true bearings";
  ASSERT_FALSE(onTruthSide(last_before->position))
      << "the reflected bearings did not put the track on the image";

  double recovered = -1.0;
  std::size_t after = 0;
  for (const Seen& s : seen) {
    if (s.stamp < switched) {
      continue;
    }
    ++after;
    const double since = s.stamp - switched;
    const bool ok = s.status == Target::STATUS_OK;
    const bool at_truth = (s.position - truth.head<2>()).norm() < 0.5;
    const bool at_image = (s.position - image.head<2>()).norm() < 0.5;
    if (ok && at_truth && recovered < 0.0) {
      recovered = since;
    }
    if (s.stamp >= due) {
      EXPECT_TRUE(ok && at_truth) << since << " s after the first true bearing: status "
                                  << int(s.status) << " at (" << s.position.transpose() << ")";
    } else {
      EXPECT_TRUE(s.status == Target::STATUS_AMBIGUOUS || at_truth || at_image)
          << since << " s after the first true bearing: status " << int(s.status) << " at ("
          << s.position.transpose() << "), neither the person, the image nor AMBIGUOUS";
    }
  }
  EXPECT_GT(after, 25u) << "too few estimates after the switch";
  EXPECT_GE(recovered, 0.0);
  std::printf(
      "on the image before the true bearings (status %d); OK at the person %.2f s after "
      "the first true bearing (stamps)\n",
      int(last_before->status), recovered);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "locator_mirror_rostest");
  return RUN_ALL_TESTS();
}
