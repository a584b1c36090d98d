// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/placement_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/config/layout_writer.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// A 0.4 m square robot, candidates every 0.2 m (9 module points, 8 board points).
MountingRegion squareRegion() {
  MountingRegion r;
  r.outline = {{-0.2, -0.2}, {0.2, -0.2}, {0.2, 0.2}, {-0.2, 0.2}};
  r.grid_spacing = 0.2;
  r.twr_count = 2;
  r.twr_min_spacing = 0.1;
  r.aoa_count = 0;
  r.aoa_min_spacing = 0.1;
  r.target.min_range = 2.0;
  r.target.max_range = 4.0;
  r.target.range_step = 2.0;
  r.target.angle_step = deg2rad(10.0);
  return r;
}

/// Targets only ahead of the robot (+-30 deg).
MountingRegion squareAhead() {
  MountingRegion r = squareRegion();
  r.target.from = deg2rad(-30.0);
  r.target.to = deg2rad(30.0);
  return r;
}

Placement bruteForceBest(const PlacementProblem& p) {
  // Independent of the enumerator: every pair scored from scratch.
  Placement best;
  PlacementScore best_score;
  best_score.objective = best_score.mean = INFINITY;
  for (int a = 0; a < static_cast<int>(p.modules.size()); ++a) {
    for (int b = a + 1; b < static_cast<int>(p.modules.size()); ++b) {
      const Placement candidate{{a, b}, {}};
      if (!feasiblePlacement(p, candidate)) {
        continue;
      }
      const PlacementScore s = scorePlacement(p, candidate);
      if (betterScore(s, best_score)) {
        best_score = s;
        best = candidate;
      }
    }
  }
  return best;
}

TEST(PlacementSearch, ExhaustiveFindsTheWidestBaselineAcrossTheTargets) {
  // Two ranges to targets ahead: the bound is smallest with the widest baseline across the
  // line of sight, i.e. the modules 0.4 m apart along y (known optimum by geometry).
  for (const auto objective :
       {PlacementObjective::kMean, PlacementObjective::kP90, PlacementObjective::kMax}) {
    MountingRegion region = squareAhead();
    region.objective = objective;
    const PlacementProblem p = buildPlacementProblem(region, AdvisorConfig{});
    ASSERT_EQ(p.modules.size(), 9u);
    const SearchResult r = exhaustiveSearch(p, 1e6);
    ASSERT_EQ(r.best.modules.size(), 2u);
    const Eigen::Vector3d a = p.modules[static_cast<std::size_t>(r.best.modules[0])].position;
    const Eigen::Vector3d b = p.modules[static_cast<std::size_t>(r.best.modules[1])].position;
    EXPECT_NEAR(std::abs(a.y() - b.y()), 0.4, 1e-9) << toString(objective);
    EXPECT_EQ(r.evaluations, 36u);  // C(9, 2): every pair is 0.2 m apart or more
    const Placement brute = bruteForceBest(p);
    EXPECT_EQ(r.best.modules, brute.modules);
    EXPECT_NEAR(r.score.objective, scorePlacement(p, brute).objective, 1e-12);
  }
}

TEST(PlacementSearch, ExhaustivePicksTheBoardFacingTheTargets) {
  MountingRegion region = squareAhead();
  region.twr_count = 1;
  region.aoa_count = 1;
  const PlacementProblem p = buildPlacementProblem(region, AdvisorConfig{});
  ASSERT_EQ(p.boards.size(), 8u);  // two per edge of the 0.4 m square
  const SearchResult r = exhaustiveSearch(p, 1e6);
  ASSERT_EQ(r.best.boards.size(), 1u);
  const MountCandidate& board = p.boards[static_cast<std::size_t>(r.best.boards[0])];
  EXPECT_NEAR(board.yaw, 0.0, 1e-9);  // the front edge, facing ahead
  EXPECT_NEAR(board.position.x(), 0.2, 1e-9);
  EXPECT_TRUE(std::isfinite(r.score.max));
}

TEST(PlacementSearch, ScoreMatchesTheAdvisorsBoundAtEveryTarget) {
  MountingRegion region = squareRegion();
  region.twr_count = 2;
  region.aoa_count = 2;
  const AdvisorConfig advisor;
  const PlacementProblem p = buildPlacementProblem(region, advisor);
  const Placement placement{{0, 8}, {1, 5}};
  ASSERT_TRUE(feasiblePlacement(p, placement));
  const Layout layout = placementLayout(p, placement);
  double sum = 0.0;
  double worst = 0.0;
  for (const Eigen::Vector3d& t : p.targets) {
    const PointBound b = boundAt(layout, t, advisor);
    ASSERT_TRUE(b.observable);
    sum += b.rms;
    worst = std::max(worst, b.rms);
  }
  const PlacementScore s = scorePlacement(p, placement);
  EXPECT_NEAR(s.mean, sum / static_cast<double>(p.targets.size()), 1e-9);
  EXPECT_NEAR(s.max, worst, 1e-9);
  EXPECT_LE(s.p90, s.max);
}

TEST(PlacementSearch, GreedyIsNeverWorseThanItsStart) {
  MountingRegion region = squareRegion();
  region.grid_spacing = 0.1;
  region.twr_count = 3;
  region.twr_min_spacing = 0.2;
  region.aoa_count = 2;
  region.objective = PlacementObjective::kMax;
  const PlacementProblem p = buildPlacementProblem(region, AdvisorConfig{});
  std::mt19937_64 rng(7);
  for (int i = 0; i < 10; ++i) {
    const Placement start = randomPlacement(p, rng);
    ASSERT_TRUE(feasiblePlacement(p, start));
    const PlacementScore before = scorePlacement(p, start);
    const SearchResult r = greedySearch(p, start);
    EXPECT_TRUE(feasiblePlacement(p, r.best));
    EXPECT_LE(r.score.objective, before.objective + 1e-12);
    EXPECT_GE(r.evaluations, 1u);
    EXPECT_NEAR(r.score.objective, scorePlacement(p, r.best).objective, 1e-12);
  }
}

TEST(PlacementSearch, GreedyAndRandomNeverBeatTheExhaustiveOptimum) {
  MountingRegion region = squareRegion();
  region.grid_spacing = 0.1;
  region.twr_count = 3;
  region.twr_min_spacing = 0.2;
  const PlacementProblem p = buildPlacementProblem(region, AdvisorConfig{});
  const SearchResult best = exhaustiveSearch(p, 1e6);
  EXPECT_GE(greedyRestarts(p, 5, 1).score.objective, best.score.objective - 1e-12);
  EXPECT_GE(randomSearch(p, 50, 1).score.objective, best.score.objective - 1e-12);
  // Deterministic for a seed.
  EXPECT_EQ(greedyRestarts(p, 5, 3).best.modules, greedyRestarts(p, 5, 3).best.modules);
}

TEST(PlacementSearch, ModulesInOneLineAreNotAPlacement) {
  MountingRegion region = squareRegion();
  region.twr_count = 3;
  region.twr_min_off_line = 1e-6;  // exactly in one line only
  PlacementProblem p = buildPlacementProblem(region, AdvisorConfig{});
  // Candidates row by row from (-0.2, -0.2): 0, 4, 8 is the diagonal, 0, 1, 3 a triangle.
  EXPECT_FALSE(feasiblePlacement(p, Placement{{0, 4, 8}, {}}));
  EXPECT_TRUE(feasiblePlacement(p, Placement{{0, 1, 3}, {}}));
  const SearchResult r = exhaustiveSearch(p, 1e6);
  EXPECT_TRUE(feasiblePlacement(p, r.best));
  EXPECT_EQ(r.evaluations, 76u);  // C(9, 3) less the 8 lines of three
  // The default rule also drops flat triangles (rms off their line < 5 cm).
  p.region.twr_min_off_line = 0.05;
  EXPECT_LT(exhaustiveSearch(p, 1e6).evaluations, 76u);
  EXPECT_FALSE(feasiblePlacement(p, Placement{{0, 4, 5}, {}}));  // 4.2 cm off their line
}

TEST(PlacementSearch, KeepOutZonesHoldNoSensor) {
  MountingRegion region = squareRegion();
  region.grid_spacing = 0.1;
  region.aoa_count = 2;
  const Polygon zone{{0.0, -0.25}, {0.25, -0.25}, {0.25, 0.25}, {0.0, 0.25}};  // front half
  region.keep_out = {zone};
  const PlacementProblem p = buildPlacementProblem(region, AdvisorConfig{});
  for (const auto& c : p.modules) {
    EXPECT_FALSE(insidePolygon(zone, c.position.head<2>())) << c.position.transpose();
  }
  for (const auto& c : p.boards) {
    EXPECT_FALSE(insidePolygon(zone, c.position.head<2>())) << c.position.transpose();
  }
  EXPECT_EQ(p.modules.size(), 10u);  // x = -0.2 and -0.1, five rows each
  const SearchResult r = greedyRestarts(p, 3, 1);
  for (const auto& m : placementLayout(p, r.best).twr_modules) {
    EXPECT_LT(m.position.x(), 0.0);
  }
}

TEST(PlacementSearch, CandidatesStayInANonConvexOutlineAndBoardsFaceOut) {
  MountingRegion region = squareRegion();
  // An L: the square without its front-left quarter.
  region.outline = {{-0.2, -0.2}, {0.2, -0.2}, {0.2, 0.0}, {0.0, 0.0}, {0.0, 0.2}, {-0.2, 0.2}};
  region.grid_spacing = 0.05;
  region.aoa_count = 1;
  const PlacementProblem p = buildPlacementProblem(region, AdvisorConfig{});
  EXPECT_FALSE(insidePolygon(region.outline, {0.1, 0.1}));
  for (const auto& c : p.modules) {
    EXPECT_TRUE(insidePolygon(region.outline, c.position.head<2>())) << c.position.transpose();
    EXPECT_FALSE(c.position.x() > 1e-9 && c.position.y() > 1e-9) << c.position.transpose();
  }
  for (const auto& c : p.boards) {
    const Eigen::Vector2d out(std::cos(c.yaw), std::sin(c.yaw));
    EXPECT_TRUE(insidePolygon(region.outline, c.position.head<2>()));
    EXPECT_FALSE(insidePolygon(region.outline, c.position.head<2>() + 0.01 * out))
        << "board at " << c.position.transpose() << " faces inward";
  }
}

TEST(PlacementSearch, TooLargeExhaustiveSearchIsRefused) {
  MountingRegion region = squareRegion();
  region.grid_spacing = 0.05;  // 81 module candidates
  region.twr_count = 4;
  const PlacementProblem p = buildPlacementProblem(region, AdvisorConfig{});
  EXPECT_GT(combinationCount(p), 1e6);
  try {
    exhaustiveSearch(p, 1e5);
    FAIL() << "expected SearchTooLarge";
  } catch (const SearchTooLarge& e) {
    EXPECT_NE(std::string(e.what()).find("greedy"), std::string::npos) << e.what();
  }
}

TEST(PlacementSearch, TooManySensorsForTheRegionFailNamingTheCount) {
  MountingRegion region = squareRegion();
  region.twr_count = 10;  // 9 candidates
  try {
    buildPlacementProblem(region, AdvisorConfig{});
    FAIL() << "expected ParamError";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), "twr_modules.count");
  }
}

TEST(PlacementSearch, WrittenLayoutLoadsWithTheSensorsPlaced) {
  MountingRegion region = squareRegion();
  region.aoa_count = 2;
  const PlacementProblem p = buildPlacementProblem(region, AdvisorConfig{});
  const Placement placement{{0, 8}, {1, 5}};
  const Layout layout = placementLayout(p, placement);
  const Layout read = parseLayout(writeLayout(layout, {"test"}), "test");
  ASSERT_EQ(read.twr_modules.size(), 2u);
  ASSERT_EQ(read.aoa_boards.size(), 2u);
  EXPECT_EQ(read.target_anchor_id, "DA12");
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(read.twr_modules[i].position.isApprox(layout.twr_modules[i].position, 1e-6));
    EXPECT_TRUE(read.aoa_boards[i].position.isApprox(layout.aoa_boards[i].position, 1e-6));
    const Eigen::Vector3d axis = read.aoa_boards[i].orientation * Eigen::Vector3d::UnitX();
    const Eigen::Vector3d want = layout.aoa_boards[i].orientation * Eigen::Vector3d::UnitX();
    EXPECT_NEAR((axis - want).norm(), 0.0, 1e-6);
  }
}

// ---- the region file ----

const char* kRegion = R"(
name: test
outline: [[-0.2, -0.2], [0.2, -0.2], [0.2, 0.2], [-0.2, 0.2]]
grid_spacing: 0.1
twr_modules: {count: 2, height: 0.1, min_spacing: 0.2}
aoa_boards: {count: 1, kind: ant_b10}
target: {min_range: 2, max_range: 4, angle_step_deg: 15}
objective: max
)";

std::string withLine(const std::string& from, const std::string& to) {
  std::string text = kRegion;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

ParamError regionError(const std::string& text) {
  try {
    parseMountingRegion(text, "test.yaml");
  } catch (const ParamError& e) {
    return e;
  }
  ADD_FAILURE() << "no ParamError for:\n" << text;
  return ParamError("", "", "");
}

TEST(MountingRegionFile, ParsesEveryField) {
  const MountingRegion r = parseMountingRegion(kRegion, "test.yaml");
  EXPECT_EQ(r.name, "test");
  EXPECT_EQ(r.outline.size(), 4u);
  EXPECT_EQ(r.twr_count, 2);
  EXPECT_DOUBLE_EQ(r.twr_min_spacing, 0.2);
  EXPECT_EQ(r.aoa_count, 1);
  EXPECT_EQ(r.aoa_kind, AoaBoardKind::kAntB10);
  EXPECT_DOUBLE_EQ(r.target.min_range, 2.0);
  EXPECT_NEAR(r.target.angle_step, deg2rad(15.0), 1e-12);
  EXPECT_EQ(r.objective, PlacementObjective::kMax);
  EXPECT_EQ(r.target.points().size(), 2u * 24u);
}

TEST(MountingRegionFile, MisspeltKeysAreRejectedByName) {
  const ParamError top = regionError(withLine("grid_spacing: 0.1", "grid_spcing: 0.1"));
  EXPECT_EQ(top.name(), "grid_spcing");
  EXPECT_NE(std::string(top.what()).find("grid_spacing"), std::string::npos) << top.what();
  EXPECT_EQ(regionError(withLine("min_spacing: 0.2", "min_spacng: 0.2")).name(),
            "twr_modules.min_spacng");
  EXPECT_EQ(regionError(withLine("angle_step_deg", "angle_stepdeg")).name(),
            "target.angle_stepdeg");
}

TEST(MountingRegionFile, BadValuesAreRejectedWithTheirValue) {
  const ParamError objective = regionError(withLine("objective: max", "objective: median"));
  EXPECT_EQ(objective.name(), "objective");
  EXPECT_NE(std::string(objective.what()).find("median"), std::string::npos);
  EXPECT_EQ(regionError(withLine("grid_spacing: 0.1", "grid_spacing: -1")).name(), "grid_spacing");
  EXPECT_EQ(regionError(withLine("count: 2", "count: 2.5")).name(), "twr_modules.count");
  EXPECT_EQ(regionError(withLine("kind: ant_b10", "kind: antb10")).name(), "aoa_boards.kind");
  EXPECT_EQ(regionError(withLine("[0.2, -0.2], [0.2, 0.2], [-0.2, 0.2]]", "[0.2, -0.2]]")).name(),
            "outline");
  EXPECT_EQ(regionError(withLine("max_range: 4", "max_range: 1")).name(), "target.max_range");
}

TEST(MountingRegionFile, ShippedRegionsLoadAndHoldTheirSensors) {
  for (const std::string name : {"spot", "tracked"}) {
    const MountingRegion r =
        loadMountingRegionFile(std::string(RF_CONFIG_DIR) + "/placement/" + name + "_region.yaml");
    EXPECT_EQ(r.name, name);
    const PlacementProblem p = buildPlacementProblem(r, AdvisorConfig{});
    EXPECT_GE(p.modules.size(), static_cast<std::size_t>(r.twr_count));
    EXPECT_GE(p.boards.size(), static_cast<std::size_t>(r.aoa_count));
  }
}

}  // namespace
}  // namespace estimation
}  // namespace radio_follow
