// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/mounting_region.hpp"
#include "radio_follow/estimation/placement_advisor.hpp"

namespace radio_follow {
namespace estimation {

/// The placement search problem: candidates, target grid, and every candidate's Fisher
/// information at every target (the advisor's observation model, advisorObservations, for a
/// layout of that one sensor). Sensors' measurements are independent, so a layout's
/// information is the sum of its sensors' and a layout is scored without re-deriving any
/// Jacobian (seed 004's Algorithms 2 and 3 recompute the whole CRLB per layout).
struct PlacementProblem {
  MountingRegion region;
  AdvisorConfig advisor;  ///< planar / use_elevation as the advisor's map
  std::vector<MountCandidate> modules;
  std::vector<MountCandidate> boards;
  std::vector<Eigen::Vector3d> targets;
  std::vector<Eigen::Matrix3d> module_info;  ///< [candidate * targets.size() + target]
  std::vector<Eigen::Matrix3d> board_info;
};

/// Builds the candidates and the information tables. Throws ParamError when the region or
/// the advisor configuration is invalid or there are fewer candidates than sensors.
PlacementProblem buildPlacementProblem(const MountingRegion& region, const AdvisorConfig& advisor);

/// A layout as candidate indices: `modules` into PlacementProblem::modules, `boards` into
/// PlacementProblem::boards (each sorted ascending, no repeats).
struct Placement {
  std::vector<int> modules;
  std::vector<int> boards;
};

/// Statistics of the bound b = sqrt(trace CRLB) over the target grid, m. An unobservable
/// point counts as b = infinity (the mean and max are then infinite; the p90 is when more
/// than 10 % are).
struct PlacementScore {
  double objective = 0.0;  ///< the region's objective statistic
  double mean = 0.0;
  double p90 = 0.0;
  double max = 0.0;
  double unobservable_fraction = 0.0;
};

/// True when `a` is better than `b`: smaller objective; ties (1e-12 m) by the mean.
bool betterScore(const PlacementScore& a, const PlacementScore& b);

/// Scores a placement against the problem's targets.
PlacementScore scorePlacement(const PlacementProblem& problem, const Placement& placement);

/// True when the placement has the region's counts, valid distinct indices and respects
/// the mounting rules: the minimum spacings and, with 3 or more modules, twr_min_off_line.
bool feasiblePlacement(const PlacementProblem& problem, const Placement& placement);

/// Result of a search: the best placement found and the work spent.
struct SearchResult {
  Placement best;
  PlacementScore score;
  std::size_t evaluations = 0;  ///< placements scored
  std::size_t starts = 0;       ///< greedy: starting placements; random: samples
};

/// The number of placements exhaustiveSearch would enumerate before the spacing rules
/// prune: C(modules, twr_count) x C(boards, aoa_count), as a double (it overflows).
double combinationCount(const PlacementProblem& problem);

/// Thrown by exhaustiveSearch when combinationCount exceeds its limit.
class SearchTooLarge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Seed 004's Algorithm 2: every feasible placement scored, the best kept (the first in
/// lexicographic order among equals). Throws SearchTooLarge when combinationCount >
/// `max_combinations`, naming the count and suggesting the greedy search.
SearchResult exhaustiveSearch(const PlacementProblem& problem, double max_combinations);

/// Steepest-descent local search from `start` (feasible): every move of one sensor to
/// another candidate is scored, the best improving move applied, until none improves.
/// Never returns a placement worse than `start`.
SearchResult greedySearch(const PlacementProblem& problem, const Placement& start);

/// A uniformly drawn feasible placement (each sensor among the candidates the earlier ones
/// leave free). Throws ParamError when 1000 draws find none (the region cannot hold the
/// sensors that far apart).
Placement randomPlacement(const PlacementProblem& problem, std::mt19937_64& rng);

/// greedySearch from `restarts` random feasible placements (random-restart hill climbing),
/// the best kept. Deterministic for a seed.
SearchResult greedyRestarts(const PlacementProblem& problem, int restarts, std::uint64_t seed);

/// Seed 004's Algorithm 3 without its stopping limit: `samples` random feasible placements,
/// the best kept. Deterministic for a seed.
SearchResult randomSearch(const PlacementProblem& problem, int samples, std::uint64_t seed);

/// Which sensor count minimumSensors raises when the limit is not met.
enum class GrowSensors { kModules, kBoards, kBoth };

/// Seed 004's Algorithm 3 loop around a search: the fewest sensors that reach
/// objective <= limit. Starting from the region's counts, `search` (randomSearch or
/// greedyRestarts with `effort` samples or starts, seeded `seed`) is run; while the best
/// objective exceeds `limit` one sensor is added (kBoth: whichever of +1 module and
/// +1 board reaches the smaller objective), until a count exceeds its candidates or 16.
struct MinimumSensorsResult {
  bool reached = false;  ///< false: the counts ran out first (the last search is kept)
  int modules = 0;
  int boards = 0;
  SearchResult search;          ///< the last (successful) search
  std::size_t evaluations = 0;  ///< summed over every count tried
};
MinimumSensorsResult minimumSensors(const MountingRegion& region, const AdvisorConfig& advisor,
                                    double limit, GrowSensors grow, bool greedy, int effort,
                                    std::uint64_t seed);

/// The placement as a layout the locator loads: modules "0001".. (replace with the real
/// module IDs) with identity calibrations, boards "aoa1".. facing their candidate's yaw.
Layout placementLayout(const PlacementProblem& problem, const Placement& placement);

}  // namespace estimation
}  // namespace radio_follow
