// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/placement_advisor.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/models/sensor_tables.hpp"

namespace radio_follow {
namespace estimation {
namespace {

TwrModule module(const std::string& id, double x, double y, double z) {
  TwrModule m;
  m.id = id;
  m.frame_id = "uwb_" + id;
  m.position = {x, y, z};
  return m;
}

AoaBoard board(const std::string& id, double x, double y, double z, double yaw_deg) {
  AoaBoard b;
  b.id = id;
  b.frame_id = "aoa_" + id;
  b.position = {x, y, z};
  b.orientation = Eigen::AngleAxisd(deg2rad(yaw_deg), Eigen::Vector3d::UnitZ());
  return b;
}

Layout layoutOf(std::vector<TwrModule> modules, std::vector<AoaBoard> boards = {}) {
  Layout layout;
  layout.target_anchor_id = "DA12";
  layout.twr_modules = std::move(modules);
  layout.aoa_boards = std::move(boards);
  layout.validate();
  return layout;
}

Layout square() {
  return layoutOf({module("1", 0.3, 0.25, 0.4), module("2", 0.3, -0.25, 0.4),
                   module("3", -0.3, -0.25, 0.4), module("4", -0.3, 0.25, 0.4)});
}

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

AdvisorConfig smallGrid() {
  AdvisorConfig config;
  config.extent = 6.0;
  config.resolution = 0.5;
  return config;
}

TEST(PlacementAdvisor, SymmetricLayoutGivesMirrorSymmetricMap) {
  const BoundMap map = computeMap(square(), smallGrid());
  const std::size_t n = map.coordinates.size();
  ASSERT_EQ(n, 25u);
  EXPECT_DOUBLE_EQ(map.coordinates[12], 0.0);
  for (std::size_t iy = 0; iy < n; ++iy) {
    for (std::size_t ix = 0; ix < n; ++ix) {
      const PointBound& b = map.at(ix, iy);
      ASSERT_TRUE(b.observable) << ix << "," << iy;
      EXPECT_NEAR(b.rms, map.at(n - 1 - ix, iy).rms, 1e-9 * b.rms);
      EXPECT_NEAR(b.rms, map.at(ix, n - 1 - iy).rms, 1e-9 * b.rms);
      EXPECT_LE(b.worst_axis, b.rms + 1e-12);
      EXPECT_GE(b.worst_axis, b.rms / std::sqrt(2.0) - 1e-12);
    }
  }
}

TEST(PlacementAdvisor, MoreModulesTightenTheBound) {
  const Layout four = square();
  Layout three = four;
  three.twr_modules.pop_back();
  const AdvisorConfig config;
  for (const double azimuth : {0.3, 1.2, 2.5, 4.0, 5.5}) {
    for (const double r : {2.0, 4.0, 8.0}) {
      const Eigen::Vector3d p(r * std::cos(azimuth), r * std::sin(azimuth), 1.0);
      const PointBound b3 = boundAt(three, p, config);
      const PointBound b4 = boundAt(four, p, config);
      ASSERT_TRUE(b3.observable && b4.observable);
      EXPECT_LT(b4.rms, b3.rms) << "azimuth " << azimuth << " r " << r;
    }
  }
}

TEST(PlacementAdvisor, TwoOrthogonalRangesMatchHandComputation) {
  // Target at (4, 0, 1): the module at the origin sees it along +x, the one at (4, -4)
  // along +y, both 4 m away. Fisher = diag(1, 1) / sigma(4)^2, so in 2D
  // sqrt(tr CRLB) = sqrt(2) sigma(4) and the worst axis is sigma(4).
  const Layout layout = layoutOf({module("a", 0.0, 0.0, 1.0), module("b", 4.0, -4.0, 1.0)});
  const double sigma = models::uwbRangeError(4.0).sigma;
  ASSERT_GT(sigma, 0.0);
  const PointBound b = boundAt(layout, {4.0, 0.0, 1.0}, AdvisorConfig{});
  ASSERT_TRUE(b.observable);
  EXPECT_NEAR(b.rms, std::sqrt(2.0) * sigma, 1e-12);
  EXPECT_NEAR(b.worst_axis, sigma, 1e-12);
}

TEST(PlacementAdvisor, RangePlusBearingMatchesHandComputation) {
  // Range along the line of sight, bearing across it with Jacobian (I - u u^T) / r
  // (seed 004 eq. 4.51): in 2D the bound is diag(sigma_r^2, r^2 sigma_az^2).
  const double r = 4.0;
  const Layout layout = layoutOf({module("a", 0.0, 0.0, 1.0)}, {board("front", 0, 0, 1, 0)});
  const double sigma_r = models::uwbRangeError(r).sigma;
  const double sigma_az = models::aoaError(AoaBoardKind::kXplrAoa1, 0.0, r).azimuth_sigma;
  const PointBound b = boundAt(layout, {r, 0.0, 1.0}, AdvisorConfig{});
  ASSERT_TRUE(b.observable);
  EXPECT_EQ(b.bearings, 1);
  EXPECT_NEAR(b.rms, std::hypot(sigma_r, r * sigma_az), 1e-12);
  EXPECT_NEAR(b.worst_axis, std::max(sigma_r, r * sigma_az), 1e-12);
  // Behind the board: no bearing, one range, so the position is not observable.
  const PointBound behind = boundAt(layout, {-r, 0.0, 1.0}, AdvisorConfig{});
  EXPECT_FALSE(behind.observable);
  EXPECT_EQ(behind.bearings, 0);
  EXPECT_TRUE(std::isinf(behind.rms));
}

TEST(PlacementAdvisor, FrontOnlyBoardFlagsTheRearSectors) {
  const Layout layout = layoutOf({module("a", 0.0, 0.0, 0.5)}, {board("front", 0.1, 0, 0.5, 0)});
  AdvisorConfig config;
  config.sectors = 8;
  const PlacementSummary summary = summarize(layout, config);
  ASSERT_EQ(summary.sectors.size(), 8u);
  EXPECT_FALSE(summary.sectors[0].weak);  // ahead
  EXPECT_DOUBLE_EQ(summary.sectors[4].centre_deg, 180.0);
  EXPECT_TRUE(summary.sectors[4].weak);
  EXPECT_TRUE(std::isinf(summary.sectors[4].worst_ratio));
  for (const auto& ring : summary.rings) {
    EXPECT_TRUE(std::isinf(ring.worst));
    EXPECT_GT(ring.unobservable_fraction, 0.4);
    EXPECT_LT(ring.unobservable_fraction, 0.7);
    EXPECT_TRUE(std::isfinite(ring.median));
  }
  EXPECT_TRUE(mentions(summary.warnings, "unobservable"));
  EXPECT_TRUE(mentions(summary.warnings, "field of view covers"));
}

TEST(PlacementAdvisor, SymmetricLayoutHasNoWeakSectorAndGrowingRings) {
  const PlacementSummary summary = summarize(square(), AdvisorConfig{});
  ASSERT_EQ(summary.rings.size(), 3u);
  for (const auto& s : summary.sectors) {
    EXPECT_FALSE(s.weak) << s.centre_deg;
  }
  // Range-only: the lateral error grows with distance.
  EXPECT_LT(summary.rings[0].median, summary.rings[1].median);
  EXPECT_LT(summary.rings[1].median, summary.rings[2].median);
  EXPECT_TRUE(summary.warnings.empty()) << summary.warnings.front();
}

TEST(PlacementAdvisor, WarnsAboutCollinearModules) {
  const Layout line = layoutOf(
      {module("1", -0.4, 0.0, 0.3), module("2", 0.0, 0.0, 0.3), module("3", 0.4, 0.0, 0.3)});
  EXPECT_TRUE(mentions(layoutWarnings(line, AdvisorConfig{}), "collinear"));
  EXPECT_FALSE(mentions(layoutWarnings(square(), AdvisorConfig{}), "collinear"));
  // A board facing the target resolves the mirror side.
  Layout with_board = line;
  with_board.aoa_boards.push_back(board("front", 0, 0, 0.3, 0));
  EXPECT_FALSE(mentions(layoutWarnings(with_board, AdvisorConfig{}), "collinear"));
}

TEST(PlacementAdvisor, WarnsAboutModulesCloserThanThirtyCentimetres) {
  const Layout close = layoutOf(
      {module("1", 0.0, 0.0, 0.3), module("2", 0.2, 0.0, 0.3), module("3", 0.0, 0.5, 0.3)});
  const auto warnings = layoutWarnings(close, AdvisorConfig{});
  EXPECT_TRUE(mentions(warnings, "TWR modules 1 and 2 are 0.20 m apart"));
  EXPECT_FALSE(mentions(warnings, "1 and 3"));
  EXPECT_FALSE(mentions(layoutWarnings(square(), AdvisorConfig{}), "apart"));
}

TEST(PlacementAdvisor, WarnsAboutTooFewOrCoplanarModulesIn3d) {
  AdvisorConfig config;
  config.planar = false;
  Layout three = square();
  three.twr_modules.pop_back();
  EXPECT_TRUE(mentions(layoutWarnings(three, config), "too few TWR modules for 3D"));
  EXPECT_TRUE(mentions(layoutWarnings(square(), config), "lie in one plane"));
  Layout raised = square();
  raised.twr_modules[0].position.z() = 1.0;
  EXPECT_FALSE(mentions(layoutWarnings(raised, config), "plane"));
  EXPECT_TRUE(layoutWarnings(square(), AdvisorConfig{}).empty());
}

TEST(PlacementAdvisor, FourBoardsCoverAllDirectionsUnlessTheirFieldOfViewIsNarrow) {
  std::vector<AoaBoard> boards{board("front", 0.065, 0, 0.25, 0), board("left", 0, 0.065, 0.25, 90),
                               board("back", -0.065, 0, 0.25, 180),
                               board("right", 0, -0.065, 0.25, -90)};
  const Layout cube = layoutOf({module("a", 0, 0, 0.35)}, boards);
  EXPECT_FALSE(mentions(layoutWarnings(cube, AdvisorConfig{}), "field of view"));
  for (auto& b : boards) {
    b.field_of_view = deg2rad(30.0);
  }
  const auto warnings =
      layoutWarnings(layoutOf({module("a", 0, 0, 0.35)}, boards), AdvisorConfig{});
  EXPECT_EQ(std::count_if(warnings.begin(), warnings.end(),
                          [](const std::string& w) {
                            return w.find("field of view covers") != std::string::npos;
                          }),
            4);
}

TEST(PlacementAdvisor, RejectsInvalidConfig) {
  AdvisorConfig config;
  config.resolution = -0.1;
  EXPECT_THROW(config.validate(), ParamError);
  config = AdvisorConfig{};
  config.extent = std::nan("");
  EXPECT_THROW(computeMap(square(), config), ParamError);
  config = AdvisorConfig{};
  config.rings = {2.0, -1.0};
  EXPECT_THROW(summarize(square(), config), ParamError);
  config = AdvisorConfig{};
  config.weak_factor = 0.5;
  EXPECT_THROW(config.validate(), ParamError);
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
