// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/rss_direction.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/particle_filter.hpp"
#include "radio_follow/models/sensor_tables.hpp"
#include "radio_follow/sim/virtual_sensors.hpp"

namespace radio_follow {
namespace estimation {
namespace {

Layout shippedLayout(const std::string& name) {
  return loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/" + name);
}

AoaBoard board(const std::string& id, double yaw_deg, AoaBoardKind kind = AoaBoardKind::kXplrAoa1) {
  AoaBoard b;
  b.id = id;
  b.kind = kind;
  b.position =
      Eigen::Vector3d(0.1 * std::cos(deg2rad(yaw_deg)), 0.1 * std::sin(deg2rad(yaw_deg)), 0.25);
  b.orientation = Eigen::AngleAxisd(deg2rad(yaw_deg), Eigen::Vector3d::UnitZ());
  return b;
}

TEST(RssDirectionLikelihood, PeaksTowardTheStrongerBoardAndIsSymmetric) {
  const RssDirectionLikelihood model;
  // Board a reads 6 dB more: the tag is most likely straight ahead of a, least behind it.
  const double d = 6.0;
  double previous = 0.0;
  for (double theta = kPi; theta >= 0.0; theta -= 0.1) {
    const double l = model(d, std::cos(theta));
    EXPECT_GT(l, previous) << "theta " << theta;  // rises all the way to a's axis
    previous = l;
    // Symmetric about the pair's axis, and swapping the boards mirrors it.
    EXPECT_DOUBLE_EQ(l, model(d, std::cos(-theta)));
    EXPECT_DOUBLE_EQ(l, model(-d, std::cos(kPi - theta)));
  }
  // No difference: both sides alike, the sides of the pair (cos 0) the likeliest.
  EXPECT_DOUBLE_EQ(model(0.0, 1.0), model(0.0, -1.0));
  EXPECT_GT(model(0.0, 0.0), model(0.0, 1.0));
}

TEST(RssDirectionLikelihood, GaussianPartIsNormalisedAndTheFloorKeepsParticlesAlive) {
  const RssDirectionLikelihood model;
  const double floor = model.outlier_share / model.floor_width;
  for (const double c : {-1.0, 0.3, 1.0}) {
    double integral = 0.0;
    for (double d = -80.0; d <= 80.0; d += 1e-3) {
      integral += (model(d, c) - floor) * 1e-3;
    }
    EXPECT_NEAR(integral, 1.0 - model.outlier_share, 1e-6) << "cos " << c;
  }
  EXPECT_GT(model(200.0, -1.0), 0.0);
  EXPECT_NEAR(model(200.0, -1.0), floor, 1e-12);

  // In the filter: a wild difference keeps every particle, weighs none of them much.
  ParticleFilter::Config config;
  config.particles = 400;
  ParticleFilter filter(config);
  std::vector<Eigen::Vector3d> ring;
  for (int k = 0; k < 400; ++k) {
    const double a = 2.0 * kPi * k / 400.0;
    ring.emplace_back(3.0 * std::cos(a), 3.0 * std::sin(a), 1.0);
  }
  filter.initialize(ring, 0.0, 0.0);
  const MeasurementFit wild = weighRssDirection(filter, {0, 0, 0.25}, 0.0, 90.0, model);
  EXPECT_LT(wild.inlier, 1e-6);
  EXPECT_GT(filter.effectiveSampleSize(), 399.0);
  // A plausible one favours the front half, symmetric about the axis, keeping the back.
  const MeasurementFit fit = weighRssDirection(filter, {0, 0, 0.25}, 0.0, 6.0, model);
  EXPECT_GT(fit.inlier, 0.9);
  double front = 0.0;
  for (std::size_t i = 0; i < filter.size(); ++i) {
    front += filter.position(i).x() > 0.0 ? filter.weight(i) : 0.0;
    EXPECT_GT(filter.weight(i), 0.0);
  }
  EXPECT_GT(front, 0.6);
  EXPECT_LT(front, 0.8);  // one difference is weak evidence: sigma 8 dB against g = 6 dB
  // +-45 deg about the axis alike (initialize() spreads the particles by 2 cm).
  EXPECT_NEAR(filter.weight(50) / filter.weight(350), 1.0, 0.01);
  EXPECT_GT(filter.weight(0), filter.weight(50));  // straight ahead the likeliest
}

TEST(OpposedBoardPairs, SpotAndCubeGiveFrontBackAndLeftRight) {
  for (const std::string name : {"spot.yaml", "cube.yaml"}) {
    const Layout layout = shippedLayout(name);
    const std::vector<RssPair> pairs = opposedBoardPairs(layout.aoa_boards);
    ASSERT_EQ(pairs.size(), 2u) << name;
    EXPECT_EQ(layout.aoa_boards[pairs[0].a].id, "front");
    EXPECT_EQ(layout.aoa_boards[pairs[0].b].id, "back");
    EXPECT_NEAR(pairs[0].axis_yaw, 0.0, 1e-9);
    EXPECT_EQ(layout.aoa_boards[pairs[1].a].id, "left");
    EXPECT_EQ(layout.aoa_boards[pairs[1].b].id, "right");
    EXPECT_NEAR(pairs[1].axis_yaw, kPi / 2.0, 1e-9);
    for (const RssPair& p : pairs) {
      EXPECT_NEAR(p.midpoint.head<2>().norm(), 0.0, 1e-9) << name;  // the cube's centre
      EXPECT_NEAR(p.midpoint.z(), 0.25, 1e-9);
    }
  }
  EXPECT_TRUE(opposedBoardPairs(shippedLayout("spot_twr.yaml").aoa_boards).empty());
  EXPECT_TRUE(opposedBoardPairs(shippedLayout("tracked.yaml").aoa_boards).empty());
}

TEST(OpposedBoardPairs, WithinTwentyDegreesOfOppositeAndOneKindOnly) {
  EXPECT_EQ(opposedBoardPairs({board("a", 0), board("b", 170)}).size(), 1u);
  EXPECT_EQ(opposedBoardPairs({board("a", 10), board("b", -165)}).size(), 1u);
  EXPECT_TRUE(opposedBoardPairs({board("a", 0), board("b", 150)}).empty());
  EXPECT_TRUE(opposedBoardPairs({board("a", 0), board("b", 90)}).empty());
  EXPECT_TRUE(opposedBoardPairs({board("a", 0), board("b", 180, AoaBoardKind::kAntB10)}).empty());
  // Each board in one pair, with the board closest to opposite.
  const std::vector<RssPair> pairs =
      opposedBoardPairs({board("a", 0), board("b", 165), board("c", 178)});
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].a, 0u);
  EXPECT_EQ(pairs[0].b, 2u);
}

TEST(RssDifferencer, PairsReadingsWithinTheWindowAndUsesEachOnce) {
  RssDifferencer differ(shippedLayout("spot.yaml").aoa_boards, 0.1);  // front left back right
  EXPECT_FALSE(differ.add(0, -50.0, 1.00));                           // front: waits for back
  EXPECT_FALSE(differ.add(1, -52.0, 1.01));                           // left: waits for right
  const auto fb = differ.add(2, -57.0, 1.05);
  ASSERT_TRUE(fb);
  EXPECT_EQ(fb->pair, 0u);
  EXPECT_DOUBLE_EQ(fb->difference, 7.0);  // front - back
  EXPECT_DOUBLE_EQ(fb->t, 1.05);
  EXPECT_FALSE(differ.add(2, -56.0, 1.08));  // the front reading is used
  const auto again = differ.add(0, -51.0, 1.10);
  ASSERT_TRUE(again);
  EXPECT_DOUBLE_EQ(again->difference, 5.0);
  // Right comes too late for left's reading.
  EXPECT_FALSE(differ.add(3, -60.0, 1.2));
  const auto lr = differ.add(1, -54.0, 1.25);
  ASSERT_TRUE(lr);
  EXPECT_EQ(lr->pair, 1u);
  EXPECT_DOUBLE_EQ(lr->difference, 6.0);  // left - right
  EXPECT_FALSE(differ.add(1, std::nan(""), 1.3));
}

// The locator forms the pairs' differences from its bearings' RSSI, only when asked to.
TEST(RssDifferencer, TheLocatorFeedsDifferencesOnlyWithRssDirection) {
  const Layout layout = shippedLayout("spot.yaml");
  for (const bool on : {false, true}) {
    LocatorConfig config;
    config.rss_direction = on;
    Locator locator(layout, config);
    std::size_t before = 0;
    for (int k = 0; k < 2; ++k) {
      const double t = 0.1 * k;
      for (const auto& m : layout.twr_modules) {
        locator.addRange(locator.layout().twrModuleIndex(m.id),
                         (Eigen::Vector3d(3.0, 0.5, 1.0) - m.position).norm(), t);
      }
      double rssi = -50.0;
      for (const auto& b : layout.aoa_boards) {
        locator.addBearing(locator.layout().aoaBoardIndex(b.id), 0.1, 0.0, rssi, t + 0.02);
        rssi -= 2.0;
      }
      before = k == 0 ? locator.tracker().stats().processed : before;
      locator.update(t + 0.05);
    }
    // The second epoch: 3 ranges, 4 bearings and, with rss_direction, 2 differences.
    EXPECT_EQ(locator.tracker().stats().processed - before, on ? 9u : 7u);
  }
}

TEST(RssDirectionLikelihood, NonPositiveGainOrSigmaIsRefusedByName) {
  for (const std::string name : {"rss_direction_gain_db", "rss_direction_sigma_db"}) {
    LocatorConfig config;
    (name == "rss_direction_gain_db" ? config.rss_direction_gain : config.rss_direction_sigma) =
        0.0;
    try {
      config.validate();
      ADD_FAILURE() << name << " = 0 was accepted";
    } catch (const ParamError& e) {
      EXPECT_EQ(e.name(), "~" + name);  // the private ROS parameter
    }
  }
}

// The defaults come from the measured tables and the documented behind drop, not from a
// fit to the simulator's output: this recomputes them from the thesis's tables.
TEST(RssDirectionLikelihood, DefaultsFollowTheMeasuredTables) {
  std::vector<double> sigmas;
  double spread = 0.0;  // largest change of the mean RSSI over +-60 deg at one distance
  for (const double distance : {2.0, 3.0, 4.0}) {
    double lo = 1e9;
    double hi = -1e9;
    for (double az = -60.0; az <= 60.0; az += 10.0) {
      const models::AoaError e = models::aoaError(AoaBoardKind::kXplrAoa1, deg2rad(az), distance);
      sigmas.push_back(e.rssi_sigma);
      lo = std::min(lo, e.rssi_mean);
      hi = std::max(hi, e.rssi_mean);
    }
    spread = std::max(spread, hi - lo);
  }
  std::sort(sigmas.begin(), sigmas.end());
  const double median = sigmas[sigmas.size() / 2];
  const double behind = sim::AoaNoise{}.behind_rssi_drop;
  std::printf(
      "XPLR-AOA-1 tables, 2-4 m, +-60 deg: median RSSI sigma %.2f dB (difference: %.2f "
      "dB); mean RSSI spread %.2f dB; behind drop %.1f dB\n",
      median, std::sqrt(2.0) * median, spread, behind);
  const LocatorConfig defaults;
  // g is the behind drop: in front the mean barely depends on the angle.
  EXPECT_DOUBLE_EQ(defaults.rss_direction_gain, behind);
  EXPECT_LT(spread, 0.5 * behind);
  // sigma: two independent readings, rounded up (never more confident than the tables).
  EXPECT_GE(defaults.rss_direction_sigma, std::sqrt(2.0) * median);
  EXPECT_LT(defaults.rss_direction_sigma, 1.1 * std::sqrt(2.0) * median);
  EXPECT_FALSE(defaults.rss_direction);  // an optional input
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
