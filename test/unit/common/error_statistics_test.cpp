// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/error_statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {
namespace {

TEST(ErrorSummary, QuantilesOfKnownValues) {
  std::vector<double> errors;
  for (int i = 1; i <= 100; ++i) {
    errors.push_back(0.01 * i);
  }
  const ErrorSummary s = summarize(errors);
  EXPECT_EQ(s.count, 100u);
  EXPECT_NEAR(s.mean, 0.505, 1e-12);
  EXPECT_NEAR(s.median, 0.51, 1e-12);  // nearest rank of 0.5 * 99 = 49.5 -> index 50
  EXPECT_NEAR(s.p95, 0.95, 1e-12);     // 0.95 * 99 = 94.05 -> index 94
  EXPECT_NEAR(s.max, 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(summarize({}).median));
}

TEST(ErrorStatistics, SectorsAreCentredOnTheFrontAndCountCounterClockwise) {
  EXPECT_EQ(ErrorStatistics::sectorOf(0.0), 0u);
  EXPECT_EQ(ErrorStatistics::sectorOf(deg2rad(22.0)), 0u);
  EXPECT_EQ(ErrorStatistics::sectorOf(deg2rad(-22.0)), 0u);
  EXPECT_EQ(ErrorStatistics::sectorOf(deg2rad(23.0)), 1u);
  EXPECT_EQ(ErrorStatistics::sectorOf(deg2rad(90.0)), 2u);
  EXPECT_EQ(ErrorStatistics::sectorOf(deg2rad(180.0)), 4u);
  EXPECT_EQ(ErrorStatistics::sectorOf(deg2rad(-180.0)), 4u);
  EXPECT_EQ(ErrorStatistics::sectorOf(deg2rad(-90.0)), 6u);
  EXPECT_EQ(ErrorStatistics::sectorOf(deg2rad(-30.0)), 7u);
}

TEST(ErrorStatistics, SplitsByDirectionAndDistance) {
  ErrorStatistics stats;
  stats.add(3.0, 0.0, 0.1);   // ahead, 3 m
  stats.add(0.0, -1.0, 0.5);  // right, 1 m
  stats.add(-9.0, 0.0, 0.9);  // behind, 9 m
  stats.add(std::nan(""), 0.0, 1.0);
  EXPECT_EQ(stats.overall().count, 3u);
  EXPECT_EQ(stats.sector(0).count, 1u);
  EXPECT_DOUBLE_EQ(stats.sector(6).median, 0.5);
  EXPECT_DOUBLE_EQ(stats.sector(4).max, 0.9);
  EXPECT_EQ(stats.band(0).count, 1u);  // 0-2 m
  EXPECT_EQ(stats.band(1).count, 1u);  // 2-4 m
  EXPECT_EQ(stats.band(2).count, 0u);  // 4-8 m
  EXPECT_EQ(stats.band(3).count, 1u);  // 8+ m
  EXPECT_EQ(ErrorStatistics::bandName(3), "8+ m");
  const std::string json = stats.toJson();
  EXPECT_NE(json.find("\"by_sector\""), std::string::npos);
  EXPECT_NE(json.find("\"median_m\": null"), std::string::npos);  // empty sectors
}

TEST(Nees2d, WeighsTheErrorByItsCovarianceAndRefusesNone) {
  EXPECT_DOUBLE_EQ(*nees2d({0.2, 0.0}, Eigen::Vector2d(0.01, 0.04).asDiagonal()), 4.0);
  EXPECT_DOUBLE_EQ(*nees2d({0.0, 0.2}, Eigen::Vector2d(0.01, 0.04).asDiagonal()), 1.0);
  EXPECT_FALSE(nees2d({0.1, 0.1}, Eigen::Matrix2d::Zero()));
  Eigen::Matrix2d nan = Eigen::Matrix2d::Identity();
  nan(0, 1) = std::nan("");
  EXPECT_FALSE(nees2d({0.1, 0.1}, nan));
}

TEST(ShareInside95, CountsWhatTheChiSquareQuantileBounds) {
  EXPECT_TRUE(std::isnan(shareInside95({})));
  EXPECT_DOUBLE_EQ(shareInside95({0.5, 5.9, 6.1, 100.0}), 0.5);
  // Draws of a consistent 2D estimate (NEES ~ chi-square, 2 dof = exponential, mean 2).
  std::vector<double> nees;
  for (int i = 0; i < 1000; ++i) {
    nees.push_back(-2.0 * std::log(1.0 - (i + 0.5) / 1000.0));
  }
  EXPECT_NEAR(shareInside95(nees), 0.95, 0.002);
}

TEST(MissAtTarget, IsTheDistanceFromTheHeadingRay) {
  const double deg = M_PI / 180.0;
  EXPECT_NEAR(missAtTarget(Eigen::Vector2d(4.0, 0.0), 0.0), 0.0, 1e-12);
  // 10 deg off at 4 m: 4 sin(10 deg) = 0.69 m.
  EXPECT_NEAR(missAtTarget(Eigen::Vector2d(4.0, 0.0), 10.0 * deg), 4.0 * std::sin(10.0 * deg),
              1e-12);
  EXPECT_NEAR(missAtTarget(Eigen::Vector2d(4.0, 0.0), -10.0 * deg), 4.0 * std::sin(10.0 * deg),
              1e-12);
  // Heading away from the person (the mirror): the ray never comes nearer than the robot.
  EXPECT_NEAR(missAtTarget(Eigen::Vector2d(3.0, 4.0), M_PI + std::atan2(4.0, 3.0)), 5.0, 1e-12);
  EXPECT_NEAR(missAtTarget(Eigen::Vector2d(0.0, 2.0), 0.0), 2.0, 1e-12);
}

TEST(HeadingStatistics, SummarisesByStatusAndOverall) {
  HeadingStatistics h;
  EXPECT_TRUE(h.empty());
  h.add("OK", 2.0, 0.1);
  h.add("OK", 4.0, 0.3);
  h.add("HEADING_ONLY", 170.0, 5.0);
  h.add("HEADING_ONLY", std::nan(""), 1.0);  // ignored
  EXPECT_EQ(h.headingError().count, 3u);
  EXPECT_EQ(h.headingError("OK").count, 2u);
  EXPECT_DOUBLE_EQ(h.headingError("HEADING_ONLY").median, 170.0);
  EXPECT_DOUBLE_EQ(h.miss("HEADING_ONLY").max, 5.0);
  EXPECT_EQ(h.headingError("DEGRADED").count, 0u);
  EXPECT_EQ(h.statuses(), (std::vector<std::string>{"HEADING_ONLY", "OK"}));
  const std::string json = h.toJson();
  EXPECT_NE(json.find("\"all\": {\"count\": 3"), std::string::npos) << json;
  EXPECT_NE(json.find("\"HEADING_ONLY\": {\"count\": 1, \"heading_error_deg\": {\"mean\": 170"),
            std::string::npos)
      << json;
}

}  // namespace
}  // namespace radio_follow
