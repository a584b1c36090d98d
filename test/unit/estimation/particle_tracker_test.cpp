// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/particle_tracker.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../../support/true_ranges.hpp"
#include "radio_follow/common/angles.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/measurement_models.hpp"
#include "radio_follow/estimation/odometry_placement.hpp"
#include "radio_follow/estimation/rss_direction.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// Noisy ranges and bearings of a layout to a target, each sensor at its own phase.
class Feeder {
 public:
  Feeder(Locator& locator, double range_sigma, double angle_sigma, unsigned seed)
      : locator_(locator), range_sigma_(range_sigma), angle_sigma_(angle_sigma), rng_(seed) {}

  /// Every module once and every board facing `bearing_target` once, within [t, t + 0.1).
  /// Positions in the odometry frame when `pose` is given (the robot there), else in the
  /// robot frame.
  void epoch(const Eigen::Vector3d& target, double t, const std::optional<Pose2>& pose,
             bool bearings = true, const std::optional<Eigen::Vector3d>& bearing_target = {}) {
    const Pose2 p = pose.value_or(Pose2{});
    const Eigen::Vector3d local = p.fromFixed(target);
    const Eigen::Vector3d seen = p.fromFixed(bearing_target.value_or(target));
    std::normal_distribution<double> range_noise(0.0, range_sigma_);
    std::normal_distribution<double> angle_noise(0.0, angle_sigma_);
    double at = t;
    for (const auto& m : locator_.layout().twr_modules) {
      locator_.addRange(locator_.layout().twrModuleIndex(m.id),
                        (local - m.position).norm() + range_noise(rng_), at, pose);
      at += 0.01;
    }
    if (!bearings) {
      return;
    }
    for (const auto& b : locator_.layout().aoa_boards) {
      if ((b.orientation.conjugate() * (seen - b.position)).x() <= 0.0) {
        continue;  // behind the board
      }
      const Eigen::Vector2d ae = predictBearing(seen, b.position, b.orientation.toRotationMatrix());
      locator_.addBearing(locator_.layout().aoaBoardIndex(b.id), ae(0) + angle_noise(rng_),
                          ae(1) + angle_noise(rng_), -60.0, at, pose);
      at += 0.01;
    }
  }

 private:
  Locator& locator_;
  double range_sigma_;
  double angle_sigma_;
  std::mt19937_64 rng_;
};

LocatorConfig particleConfig() {
  LocatorConfig config;
  config.estimator = Estimator::kParticle;
  config.azimuth_sigma = 5.0 * M_PI / 180.0;
  config.elevation_sigma = 5.0 * M_PI / 180.0;
  return config;
}

TEST(RangeLikelihood, ReflectionsMakeRangesLongNotShort) {
  RangeLikelihood model;
  EXPECT_GT(model(1.0), 10.0 * model(-1.0));  // a +1 m error is a reflection, -1 m is not
  EXPECT_GT(model(-50.0), 0.0);               // the floor: no particle is ever killed
  EXPECT_GT(model(0.0), model(0.1));
  // The Gaussian part integrates to 1 - outlier_share.
  double integral = 0.0;
  for (double e = -1.0; e <= 1.0; e += 1e-4) {
    integral += (model(e) -
                 model.outlier_share * 0.9 / model.outlier_length *
                     (e > 0.0 ? std::exp(-e / model.outlier_length) : 0.0) -
                 model.outlier_share * 0.1 / (2.0 * model.floor_width)) *
                1e-4;
  }
  EXPECT_NEAR(integral, 1.0 - model.outlier_share, 1e-3);
  model.one_sided = false;
  EXPECT_DOUBLE_EQ(model(1.0), model(-1.0));
}

TEST(ParticleFilter, SystematicResamplingKeepsTheWeights) {
  ParticleFilter::Config config;
  config.particles = 1000;
  ParticleFilter filter(config);
  filter.initialize({{0, 0, 1}, {10, 0, 1}}, 0.0, 0.0);  // alternating, 500 each
  // Three quarters of the weight on the particles near x = 10.
  filter.restrict([](const Eigen::Vector3d&) { return true; });
  const RangeLikelihood model{0.5, 1e-6, 1.0, true, 20.0};
  const MeasurementFit fit = weighRange(filter, {10, 0, 1}, 0.0, model);
  EXPECT_GT(fit.inlier, 0.99);
  EXPECT_LT(filter.effectiveSampleSize(), 600.0);
  ASSERT_TRUE(filter.resampleIfNeeded());
  std::size_t near_ten = 0;
  for (std::size_t i = 0; i < filter.size(); ++i) {
    near_ten += filter.position(i).x() > 5.0;
    EXPECT_FLOAT_EQ(filter.weight(i), 1.0 / 1000.0);  // single-precision weights
  }
  EXPECT_EQ(near_ten, 1000u);  // the far cloud explains the range at 1e-80 of the near one
  EXPECT_NEAR(filter.effectiveSampleSize(), 1000.0, 0.01);  // single-precision sums
}

TEST(ParticleFilter, AMeasurementNothingExplainsIsAnOutlier) {
  ParticleFilter::Config config;
  ParticleFilter filter(config);
  filter.initialize({{3, 0, 1}}, 0.1, 0.0);
  const MeasurementFit fit = weighRange(filter, {0, 0, 1}, 9.0, RangeLikelihood{});
  EXPECT_GT(fit.likelihood, 0.0);
  EXPECT_LT(fit.inlier, 1e-6);
  EXPECT_NEAR(filter.mean().x(), 3.0, 0.05);  // and moved nothing
}

// Single-precision particles are offsets from an origin in double: a track kilometres from
// the odometry frame's origin (a long drive) is as precise as one next to it. The same
// seed and the same measurements, once near the origin and once shifted by (5 km, -3 km),
// give the same estimate to within a millimetre (the shift's rounding); floats holding
// the absolute positions there would resolve only 0.5 mm steps, coarser than the
// prediction's position noise per step.
TEST(ParticleFilter, TracksKilometresFromTheFrameOriginAsPreciselyAsNearIt) {
  const auto run = [](const Eigen::Vector3d& shift) {
    ParticleFilter filter(ParticleFilter::Config{});
    filter.initialize({Eigen::Vector3d(3, 1, 1) + shift}, 0.5, 0.0);
    const Eigen::Vector3d modules[3] = {{0.3, 0, 1}, {-0.3, 0, 1}, {0, 0.3, 1}};
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0.0, 0.05);
    for (int k = 1; k <= 200; ++k) {
      const double t = 0.05 * k;
      const Eigen::Vector3d target(3.0 + 0.5 * t, 1.0 + 0.2 * t, 1.0);
      filter.predict(t);
      for (const Eigen::Vector3d& m : modules) {
        weighRange(filter, m + shift, (target - m).norm() + noise(rng), RangeLikelihood{});
      }
      filter.resampleIfNeeded();
    }
    return std::make_pair(Eigen::Vector3d(filter.mean() - shift), filter.covariance());
  };
  const auto [near_mean, near_covariance] = run(Eigen::Vector3d::Zero());
  const auto [far_mean, far_covariance] = run(Eigen::Vector3d(5000.0, -3000.0, 0.0));
  EXPECT_LT((near_mean - Eigen::Vector3d(8.0, 3.0, 1.0)).head<2>().norm(), 0.3);
  EXPECT_LT((far_mean - near_mean).norm(), 1e-3);
  EXPECT_LT((far_covariance - near_covariance).norm(), 1e-4);
}

// A board's sigma grows outside its field of view. A tracked cloud takes the test from
// its mean; a cold start's cloud, spread around the robot, from each particle's angle: a
// particle beyond the edge then explains an edge-biased bearing with the wide sigma
// instead of calling it an outlier.
TEST(ParticleFilter, AColdStartTestsTheFieldOfViewAtEachParticle) {
  const auto at = [](double degrees) {
    const double a = degrees * M_PI / 180.0;
    return Eigen::Vector3d(5.0 * std::cos(a), 5.0 * std::sin(a), 0.0);
  };
  BearingLikelihood model;
  model.use_elevation = false;
  model.field_of_view = 70.0 * M_PI / 180.0;
  const double reading = 40.0 * M_PI / 180.0;
  const auto likelihood = [&model](double sigma, double error) {
    const double kappa = 1.0 / (sigma * sigma);
    return (1.0 - model.outlier_share) * std::sqrt(kappa / (2.0 * M_PI)) *
               std::exp(kappa * (std::cos(error) - 1.0)) +
           model.outlier_share / (2.0 * M_PI);
  };
  const double off = 40.0 * M_PI / 180.0;  // the particle at 80 deg, the reading at 40
  for (const auto test : {BearingLikelihood::FieldOfViewTest::kCloudMean,
                          BearingLikelihood::FieldOfViewTest::kEachParticle}) {
    ParticleFilter::Config config;
    config.particles = 2;
    config.planar = false;
    ParticleFilter filter(config);
    filter.assign({at(80.0), at(40.0)}, {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()}, 0.0);
    model.field_of_view_test = test;
    weighBearing(filter, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), reading, 0.0, model);
    // The mean (60 deg) is inside: by the mean, both particles get the board's own sigma.
    const double outside_sigma = test == BearingLikelihood::FieldOfViewTest::kEachParticle
                                     ? model.azimuth_sigma * model.edge_sigma_factor
                                     : model.azimuth_sigma;
    const double outside = likelihood(outside_sigma, off);
    const double inside = likelihood(model.azimuth_sigma, 0.0);
    EXPECT_NEAR(filter.weight(0), outside / (outside + inside), 1e-5);
  }
}

// A shadowed elevation (the wearer's body between tag and board: real boards read 5-30
// deg high while the person stands) costs at most the elevation's own floor and leaves
// the azimuth's say intact. Particle A lies on the reading's azimuth, 35 deg below its
// elevation; particle B 15 deg off in azimuth, on its elevation. With one joint floor,
// the elevation's 35 deg outweighed the azimuth's 15 deg and B took the weight.
TEST(ParticleFilter, AShadowedElevationKeepsTheAzimuthsSay) {
  const auto at = [](double azimuth_deg, double elevation_deg) {
    const double a = azimuth_deg * M_PI / 180.0;
    const double e = elevation_deg * M_PI / 180.0;
    return Eigen::Vector3d(5.0 * std::cos(a), 5.0 * std::sin(a), 5.0 * std::tan(e));
  };
  const auto weightOfA = [&at](double elevation_outlier_share) {
    ParticleFilter::Config config;
    config.particles = 2;
    config.planar = false;
    ParticleFilter filter(config);
    filter.assign({at(0.0, -5.0), at(15.0, 30.0)},
                  {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()}, 0.0);
    BearingLikelihood model;
    model.elevation_outlier_share = elevation_outlier_share;
    weighBearing(filter, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), 0.0,
                 30.0 * M_PI / 180.0, model);
    return filter.weight(0);
  };
  EXPECT_GT(weightOfA(BearingLikelihood().elevation_outlier_share), 0.55);
  EXPECT_LT(weightOfA(0.0), 0.2);
}

// The first epoch of a simulated cold start that locked onto a wrong direction for 1.1 s
// (lab locator_cold_starts trial 7389, realistic profile): the person 7.4 m away at -19 deg;
// the front board sees them; the right board, the person 72 deg off its boresight (past
// its 70 deg field of view), reports an edge-biased 34 deg; the left board, the person
// behind it, a reflection. The cold start follows the board that can see the person.
// (Testing the field of view at the cloud's mean, a point near the robot, weighed the
// front board as one looking away and settled 4.5 m off, at -55 deg.) The other sensors
// stay silent here, so the start comes when the wait for them ends.
TEST(ParticleTracker, AColdStartTrustsTheBoardThatCanSeeTheTarget) {
  const LocatorConfig config = particleConfig();
  Locator locator(test::uncalibratedLayout("spot.yaml"), config);
  const Eigen::Vector3d truth(6.95, -2.43, config.height);
  const auto board = [&locator](const std::string& id) {
    for (const auto& b : locator.layout().aoa_boards) {
      if (b.id == id) {
        return b;
      }
    }
    ADD_FAILURE() << "no board " << id;
    return AoaBoard{};
  };
  const AoaBoard front = board("front");
  const Eigen::Vector2d seen =
      predictBearing(truth, front.position, front.orientation.toRotationMatrix());
  const double deg = M_PI / 180.0;
  const AoaBoard right = board("right");
  const Eigen::Vector2d beyond =
      predictBearing(truth, right.position, right.orientation.toRotationMatrix());
  ASSERT_GT(beyond(0), 70.0 * deg);  // outside the right board's field of view
  const auto& modules = locator.layout().twr_modules;
  ASSERT_TRUE(locator.addRange(locator.layout().twrModuleIndex(modules.back().id),
                               (truth - modules.back().position).norm(), 0.03));
  ASSERT_TRUE(locator.addBearing(locator.layout().aoaBoardIndex("front"), seen(0) - 3.3 * deg,
                                 seen(1), -60.0, 0.003));
  ASSERT_TRUE(locator.addBearing(locator.layout().aoaBoardIndex("left"), -55.4 * deg, 3.6 * deg,
                                 -60.0, 0.032));
  ASSERT_TRUE(locator.addBearing(locator.layout().aoaBoardIndex("right"), 34.1 * deg, 3.4 * deg,
                                 -60.0, 0.026));
  const LocatorEstimate e = locator.update(0.25);
  ASSERT_TRUE(hasPosition(e.status)) << toString(e.status);
  EXPECT_LT((e.position - truth).head<2>().norm(), 1.0) << e.position.transpose();
}

// A cold start waits for one input of every sensor, and for no longer than 0.2 s after the
// first: a silent sensor delays it, it does not stop it.
TEST(ParticleTracker, AColdStartWaitsForEverySensorBrieflyAndNoLonger) {
  const LocatorConfig config = particleConfig();
  const Eigen::Vector3d truth(3.0, 1.0, config.height);
  const auto heard = [&config, &truth](bool every_board) {
    Locator locator(test::uncalibratedLayout("spot.yaml"), config);
    for (const auto& m : locator.layout().twr_modules) {
      locator.addRange(locator.layout().twrModuleIndex(m.id), (truth - m.position).norm(), 0.01);
    }
    for (const auto& b : locator.layout().aoa_boards) {
      if (every_board || b.id == "front") {
        Eigen::Vector2d ae = predictBearing(truth, b.position, b.orientation.toRotationMatrix());
        if (std::abs(ae(0)) > M_PI / 2.0) {
          ae(0) = std::copysign(M_PI - std::abs(ae(0)), ae(0));  // behind: read mirrored
        }
        locator.addBearing(locator.layout().aoaBoardIndex(b.id), ae(0), ae(1), -60.0, 0.02);
      }
    }
    std::vector<bool> positioned;
    for (double now : {0.05, 0.15, 0.25}) {
      positioned.push_back(hasPosition(locator.update(now).status));
    }
    return positioned;
  };
  EXPECT_EQ(heard(true), (std::vector<bool>{true, true, true}));
  EXPECT_EQ(heard(false), (std::vector<bool>{false, false, true}));
}

TEST(ParticleTracker, StaticTargetSpotConvergesWithHonestCovariance) {
  const LocatorConfig config = particleConfig();
  Locator locator(test::uncalibratedLayout("spot.yaml"), config);
  Feeder feed(locator, config.range_sigma, config.azimuth_sigma, 1);
  const Eigen::Vector3d truth(3.0, 1.0, config.height);
  double nees = 0.0;
  int samples = 0;
  LocatorEstimate e;
  for (int k = 0; k < 100; ++k) {
    feed.epoch(truth, 0.1 * k, std::nullopt);
    e = locator.update(0.1 * k + 0.1);
    if (k >= 20) {
      const Eigen::Vector2d error = (e.position - truth).head<2>();
      nees += error.dot(e.covariance.topLeftCorner<2, 2>().ldlt().solve(error));
      ++samples;
    }
  }
  EXPECT_EQ(e.status, TargetStatus::kOk);
  EXPECT_EQ(e.hypotheses, 1);
  EXPECT_LT((e.position - truth).head<2>().norm(), 0.3) << e.position.transpose();
  // NEES of a consistent 2D estimate averages 2; time-correlated errors of a static
  // target make it noisy, so only gross over- or under-confidence fails.
  EXPECT_GT(nees / samples, 0.5);
  EXPECT_LT(nees / samples, 6.0);
}

// The robot drives a curve; the target stands still in the odometry frame. Tracked
// there, it stays still: the robot's own motion is not target motion.
TEST(ParticleTracker, OdometryFrameTrackingPlacesEveryMeasurementAtItsPose) {
  const LocatorConfig config = particleConfig();
  Locator locator(test::uncalibratedLayout("spot.yaml"), config);
  Feeder feed(locator, 0.02, 0.02, 2);
  const Eigen::Vector3d target(4.0, 2.0, config.height);
  LocatorEstimate e;
  Pose2 pose;
  for (int k = 0; k < 60; ++k) {
    pose.x = 0.05 * k;
    pose.yaw = 0.02 * k;  // 0.2 rad/s
    feed.epoch(target, 0.1 * k, pose);
    e = locator.update(0.1 * k + 0.1);
  }
  ASSERT_EQ(e.status, TargetStatus::kOk);
  EXPECT_TRUE(e.in_odom);
  EXPECT_LT((e.tracking_position - target).head<2>().norm(), 0.15);
  EXPECT_LT(e.tracking_velocity.head<2>().norm(), 0.3);  // standing still
  // The robot-frame output is the same point seen from the pose at the stamp.
  const Eigen::Vector3d seen = e.robot_pose.fromFixed(e.tracking_position);
  EXPECT_LT((e.position - seen).head<2>().norm(), 1e-9);
  EXPECT_NEAR(e.robot_pose.yaw, 0.02 * 59, 1e-9);
  // A measurement without a pose switches frames: the track restarts.
  locator.addRange(locator.layout().twrModuleIndex("5722"), 4.0, 6.05);
  locator.update(6.1);
  EXPECT_EQ(locator.tracker().stats().frame_switches, 1u);
}

TEST(OdometryPlacement, GapsDropMeasurementsNoOdometryFallsBackToTheRobotFrame) {
  OdometryPlacement placement(1.0);
  using D = OdometryPlacement::Decision;
  EXPECT_EQ(placement.decide(std::nullopt, 0.0), D::kRobotFrame);  // no odometry yet
  EXPECT_EQ(placement.decide(Pose2{}, 0.5), D::kPlace);
  EXPECT_EQ(placement.decide(std::nullopt, 1.2), D::kDrop);  // a TF gap: no frame switch
  EXPECT_TRUE(placement.usingOdometry());
  EXPECT_EQ(placement.decide(std::nullopt, 1.6), D::kRobotFrame);  // odometry is gone
  EXPECT_FALSE(placement.usingOdometry());
  EXPECT_EQ(placement.dropped(), 1u);
  EXPECT_EQ(placement.robotFrame(), 2u);
}

// Ranges of collinear modules alone cannot tell a person on the left from one on the
// right: the tracker says so instead of picking one. (Spot's three are not collinear
// enough for that: at 3 m their mirror fits 0.18 m RMS worse, which the tracker sees.)
TEST(ParticleTracker, CollinearModulesAloneAreAmbiguousWithTheMirrorReported) {
  LocatorConfig config = particleConfig();
  Layout layout = test::uncalibratedLayout("spot_twr.yaml");
  const double xs[3] = {0.2, -0.05, -0.3};
  for (std::size_t i = 0; i < 3; ++i) {
    layout.twr_modules[i].position = Eigen::Vector3d(xs[i], 0.0, 0.1);
  }
  Locator locator(layout, config);
  Feeder feed(locator, 0.03, 0.0, 3);
  const Eigen::Vector3d truth(0.5, 3.0, config.height);
  LocatorEstimate e;
  for (int k = 0; k < 30; ++k) {
    feed.epoch(truth, 0.1 * k, std::nullopt, false);
    e = locator.update(0.1 * k + 0.1);
  }
  EXPECT_EQ(e.status, TargetStatus::kAmbiguous);
  EXPECT_EQ(e.hypotheses, 2);
  EXPECT_GT(e.hypothesis_weight, 0.1);
  EXPECT_LT(e.hypothesis_weight, 0.9);
  // One of the two is the truth, the other its mirror across the modules' axis.
  const double to_truth =
      std::min((e.position - truth).head<2>().norm(), (e.alternative - truth).head<2>().norm());
  EXPECT_LT(to_truth, 0.5);
  EXPECT_GT((e.position - e.alternative).head<2>().norm(), 4.0);
}

/// Ranges of three exactly collinear modules (along x) and, with `rss`, the RSSI
/// differences of Spot's opposed boards, straight into a tracker: what it reports after 4 s.
TrackerOutput collinearRangesWithRss(const Eigen::Vector3d& truth, bool rss, unsigned seed) {
  Layout layout = test::uncalibratedLayout("spot_twr.yaml");
  const double xs[3] = {0.2, -0.05, -0.3};
  for (std::size_t i = 0; i < 3; ++i) {
    layout.twr_modules[i].position = Eigen::Vector3d(xs[i], 0.0, 0.1);
  }
  layout.aoa_boards = test::uncalibratedLayout("spot.yaml").aoa_boards;
  ParticleTrackerConfig config;
  config.of<RssDirectionReading>().enabled = rss;
  ParticleTracker tracker(layout, config);
  const std::vector<RssPair> pairs = opposedBoardPairs(layout.aoa_boards);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> range_noise(0.0, 0.03);
  // The simulator's physics, not the likelihood's cosine: the board with the tag behind
  // it reads 6 dB weaker, each reading with the tables' 5.4 dB spread.
  std::normal_distribution<double> rssi_noise(0.0, std::sqrt(2.0) * 5.4);
  TrackerOutput out;
  for (int k = 0; k < 40; ++k) {
    const double t = 0.1 * k;
    for (std::size_t i = 0; i < 3; ++i) {
      const double range = (truth - layout.twr_modules[i].position).norm() + range_noise(rng);
      tracker.add({t + 0.01 * static_cast<double>(i), std::nullopt, RangeReading{i, range}});
    }
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const AoaBoard& a = layout.aoa_boards[pairs[p].a];
      const bool ahead_of_a = (a.orientation.conjugate() * (truth - a.position)).x() > 0.0;
      const double difference = (ahead_of_a ? 6.0 : -6.0) + rssi_noise(rng);
      // Fed in both runs: without rss_direction the tracker skips them.
      tracker.add({t + 0.05 + 0.01 * static_cast<double>(p), std::nullopt,
                   RssDirectionReading{p, difference}});
    }
    out = tracker.update(t + 0.1);
  }
  return out;
}

// The collinear modules' ambiguity (test above) is what the opposed boards' RSSI
// difference resolves, on either side of the modules' axis.
TEST(ParticleTracker, RssDifferencesOfOpposedBoardsResolveTheCollinearMirror) {
  for (const double side : {1.0, -1.0}) {
    const Eigen::Vector3d truth(0.5, 3.0 * side, 1.0);
    for (const unsigned seed : {3u, 4u, 5u}) {
      const TrackerOutput ranges = collinearRangesWithRss(truth, false, seed);
      EXPECT_EQ(ranges.status, TargetStatus::kAmbiguous) << "side " << side << ", seed " << seed;
      EXPECT_EQ(ranges.hypotheses, 2);
      const TrackerOutput rss = collinearRangesWithRss(truth, true, seed);
      EXPECT_NE(rss.status, TargetStatus::kAmbiguous) << "side " << side << ", seed " << seed;
      EXPECT_TRUE(hasPosition(rss.status));
      EXPECT_EQ(rss.hypotheses, 1);
      EXPECT_GT(rss.hypothesis_weight, 0.99);
      EXPECT_LT((rss.position - truth).head<2>().norm(), 0.5) << rss.position.transpose();
    }
  }
}

// Bearings first point at the mirror image (a reflection, say), so the track settles
// there; then they point at the person. The estimate must leave the mirror within 1 s.
TEST(ParticleTracker, LeavesAWrongMirrorWithinOneSecondOnceTheDataDisambiguate) {
  const LocatorConfig config = particleConfig();
  Locator locator(test::uncalibratedLayout("spot.yaml"), config);
  Feeder feed(locator, 0.03, 0.03, 4);
  const Eigen::Vector3d truth(1.0, 2.5, config.height);
  const Eigen::Vector3d mirror(1.0, -2.4, config.height);  // about the modules' axis
  LocatorEstimate e;
  for (int k = 0; k < 30; ++k) {
    feed.epoch(truth, 0.1 * k, std::nullopt, true, mirror);
    e = locator.update(0.1 * k + 0.1);
  }
  ASSERT_LT(e.position.y(), 0.0) << "the track did not settle on the mirror";
  double recovered_at = -1.0;
  for (int k = 30; k < 60; ++k) {
    feed.epoch(truth, 0.1 * k, std::nullopt);
    e = locator.update(0.1 * k + 0.1);
    if (recovered_at < 0.0 && (e.position - truth).head<2>().norm() < 0.5 &&
        e.status == TargetStatus::kOk) {
      recovered_at = 0.1 * (k - 30) + 0.1;
    }
  }
  EXPECT_GT(recovered_at, 0.0);
  EXPECT_LE(recovered_at, 1.0);
  EXPECT_GE(locator.tracker().stats().mirror_swaps, 1u);
}

// A settled track on the person's side; then two boards at once report the mirror image
// (reflections). The evidence of the last second outweighs them: the estimate stays OK on
// the person and is never AMBIGUOUS. (With the evidence capped at 10 nats instead of
// fading, two such bearings, 6.4 nats each, made it AMBIGUOUS or swapped it.)
TEST(ParticleTracker, TwoReflectionsDoNotUnsettleASettledSide) {
  const LocatorConfig config = particleConfig();
  Locator locator(test::uncalibratedLayout("spot.yaml"), config);
  Feeder feed(locator, 0.03, 0.03, 5);
  const Eigen::Vector3d truth(1.0, 2.5, config.height);
  const Eigen::Vector3d mirror(1.0, -2.4, config.height);
  LocatorEstimate e;
  for (int k = 0; k < 30; ++k) {
    feed.epoch(truth, 0.1 * k, std::nullopt);
    e = locator.update(0.1 * k + 0.1);
  }
  ASSERT_EQ(e.status, TargetStatus::kOk);
  ASSERT_LT(locator.tracker().mirrorEvidence(), -10.0);
  for (const char* board : {"front", "right"}) {
    const AoaBoard* b = nullptr;
    for (const auto& candidate : locator.layout().aoa_boards) {
      b = candidate.id == board ? &candidate : b;
    }
    ASSERT_NE(b, nullptr) << board;
    const Eigen::Vector2d ae =
        predictBearing(mirror, b->position, b->orientation.toRotationMatrix());
    locator.addBearing(locator.layout().aoaBoardIndex(b->id), ae(0), ae(1), -60.0, 3.0);
  }
  for (int k = 30; k < 40; ++k) {
    feed.epoch(truth, 0.1 * k + 0.005, std::nullopt);
    e = locator.update(0.1 * k + 0.1);
    EXPECT_EQ(e.status, TargetStatus::kOk) << "at " << 0.1 * k;
    EXPECT_LT((e.position - truth).head<2>().norm(), 0.3) << "at " << 0.1 * k;
  }
  EXPECT_EQ(locator.tracker().stats().mirror_swaps, 0u);
}

TEST(ParticleTracker, OutOfOrderMeasurementsAreSortedAndFutureOnesDropped) {
  const LocatorConfig config = particleConfig();
  Locator locator(test::uncalibratedLayout("spot_twr.yaml"), config);
  const Eigen::Vector3d truth(3.0, 0.5, config.height);
  const auto& modules = locator.layout().twr_modules;
  // Newest first: the tracker applies them in stamp order.
  for (int k = 2; k >= 0; --k) {
    locator.addRange(locator.layout().twrModuleIndex(modules[k].id),
                     (truth - modules[k].position).norm(), 1.0 + 0.01 * k);
  }
  locator.addRange(locator.layout().twrModuleIndex(modules[0].id), 3.0,
                   5.0);  // 4 s ahead of the clock
  locator.update(1.05);
  EXPECT_EQ(locator.tracker().stats().future_dropped, 1u);
  EXPECT_EQ(locator.tracker().stats().cold_starts, 1u);
  EXPECT_EQ(locator.tracker().stats().late, 0u);
  // A range older than what the filter already applied is applied at the filter's time.
  locator.addRange(locator.layout().twrModuleIndex(modules[1].id),
                   (truth - modules[1].position).norm(), 1.005);
  locator.update(1.1);
  EXPECT_EQ(locator.tracker().stats().late, 1u);
}

/// One XPLR-AOA-1 board alone, at the robot's origin facing +x: the kit as sold.
Layout oneBoard() {
  Layout layout;
  AoaBoard board;
  board.id = "aoa";
  board.position = Eigen::Vector3d(0.0, 0.0, 1.0);
  layout.aoa_boards.push_back(board);
  return layout;
}

/// What a real board reports for a tag at `local` (robot frame): the direction mirrored
/// through its plane when the tag is behind, with real boards' heavy-tailed errors (a
/// Student-t with 3 degrees of freedom, 5 deg scale, plus 5 % reflections anywhere).
Eigen::Vector2d realBearing(const Eigen::Vector3d& local, std::mt19937_64& rng) {
  const Eigen::Vector3d seen(std::abs(local.x()), local.y(), local.z() - 1.0);
  std::student_t_distribution<double> tail(3.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double azimuth = std::atan2(seen.y(), seen.x()) + deg2rad(5.0) * tail(rng);
  if (unit(rng) < 0.05) {
    azimuth = M_PI * (unit(rng) - 0.5);
  }
  const double elevation = std::atan2(seen.z(), seen.head<2>().norm()) + deg2rad(5.0) * tail(rng);
  return {std::clamp(azimuth, -M_PI / 2, M_PI / 2), std::clamp(elevation, -M_PI / 2, M_PI / 2)};
}

TEST(ParticleTracker, OneBoardNeverTurnsItsBackOnAPersonInFront) {
  // Issue 35: a parked robot's board cannot tell front from back by its bearings, whose
  // errors (median 8 deg, p95 30 deg) once fitted the behind hypothesis's wider model
  // better. Behind now needs evidence: 20 runs of 60 s with a person standing and
  // walking in front never end, nor spend a second, behind.
  for (unsigned seed = 1; seed <= 20; ++seed) {
    Locator locator(oneBoard(), particleConfig());
    std::mt19937_64 rng(seed);
    int behind = 0;
    for (int k = 1; k <= 600; ++k) {
      const double t = 0.1 * k;
      // Stands at 3 m, 30 deg left, then walks across the front to 30 deg right.
      const double a = deg2rad(t < 20.0 ? 30.0 : t < 50.0 ? 30.0 - 2.0 * (t - 20.0) : -30.0);
      const Eigen::Vector3d person(3.0 * std::cos(a), 3.0 * std::sin(a), 1.0);
      const Eigen::Vector2d ae = realBearing(person, rng);
      locator.addBearing(locator.layout().aoaBoardIndex("aoa"), ae(0), ae(1), -60.0, t);
      const LocatorEstimate e = locator.update(t + 0.01);
      if (t > 2.0) {
        ASSERT_EQ(e.status, TargetStatus::kHeadingOnly) << "seed " << seed << " at " << t;
        behind += std::abs(wrapAngle(std::atan2(e.position.y(), e.position.x()) - a)) > M_PI / 2;
      }
    }
    EXPECT_LT(behind, 10) << "seed " << seed << ": updates on the wrong side";
    EXPECT_EQ(locator.tracker().stats().mirror_swaps, 0u) << "seed " << seed;
  }
}

TEST(ParticleTracker, ADirectionAloneIsARayFromTheBoard) {
  // A board 0.5 m ahead of base_link, exact bearings of a person 1.5 m from it at 50 deg
  // and no range: the reported point lies on the board's ray (from base_link it would be
  // 5 deg off at the assumed 3 m), at default_range from the board.
  Layout layout = oneBoard();
  layout.aoa_boards[0].position.x() = 0.5;
  Locator locator(layout, particleConfig());
  const double a = deg2rad(50.0);
  const Eigen::Vector3d board = layout.aoa_boards[0].position;
  LocatorEstimate e;
  for (int k = 1; k <= 100; ++k) {
    const double t = 0.1 * k;
    locator.addBearing(locator.layout().aoaBoardIndex("aoa"), a, 0.0, -60.0, t);
    e = locator.update(t + 0.01);
  }
  ASSERT_EQ(e.status, TargetStatus::kHeadingOnly);
  const Eigen::Vector2d ray = e.position.head<2>() - board.head<2>();
  EXPECT_NEAR(rad2deg(std::atan2(ray.y(), ray.x())), 50.0, 2.0);
  EXPECT_NEAR(ray.norm(), particleConfig().default_range, 1e-9);
}

TEST(ParticleTracker, OneBoardFindsAPersonBehindWhenTheRobotTurns) {
  // The evidence for behind: as the robot turns, a tag behind the board moves the other
  // way in the board's frame than its mirror image in front would. It builds up over
  // seconds of turning against bearing errors correlated over time, so one walk's outcome
  // can hang on the last bits of its arithmetic (one seed passed on one machine and
  // failed on another, likely through libm's CPU-specific sin/exp): judged over 40 walks
  // of 40 s (on the machine that wrote this, 31 of 40 ended on the person, 20 of 40
  // after 20 s; 37 swapped to the behind hypothesis at least once).
  int found = 0;
  int swapped = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    Locator locator(oneBoard(), particleConfig());
    std::mt19937_64 rng(seed);
    const Eigen::Vector3d person(-3.0, 1.0, 1.0);  // odom; behind the board throughout
    LocatorEstimate e;
    for (int k = 1; k <= 400; ++k) {
      const double t = 0.1 * k;
      Pose2 pose;
      pose.yaw = 0.4 * std::sin(0.6 * t);  // the robot turns +-23 deg in place
      const Eigen::Vector2d ae = realBearing(pose.fromFixed(person), rng);
      locator.addBearing(locator.layout().aoaBoardIndex("aoa"), ae(0), ae(1), -60.0, t, pose);
      e = locator.update(t + 0.01);
    }
    ASSERT_EQ(e.status, TargetStatus::kHeadingOnly) << "seed " << seed;
    const double heading = std::atan2(e.position.y(), e.position.x());
    found += std::abs(wrapAngle(heading - std::atan2(person.y(), person.x()))) < deg2rad(30.0);
    swapped += locator.tracker().stats().mirror_swaps >= 1;
  }
  EXPECT_GE(found, 24) << "walks that ended on the person behind, of 40";
  EXPECT_GE(swapped, 30) << "walks that took the behind hypothesis at least once, of 40";
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
