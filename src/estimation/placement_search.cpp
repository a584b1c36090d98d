// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/placement_search.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/fisher.hpp"

namespace radio_follow {
namespace estimation {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();
constexpr double kTie = 1e-12;  // m: scores closer than this are equal

/// sqrt(trace CRLB) from a summed information matrix; infinity when unobservable.
double pointBound(const Eigen::Matrix3d& info, bool planar) {
  if (planar) {
    // The 2x2 inverse in closed form: this runs once per target per scored layout.
    // Same observability test as positionCrlb (smallest eigenvalue vs 1e-10 x largest).
    const double a = info(0, 0);
    const double b = info(0, 1);
    const double c = info(1, 1);
    const double disc = std::sqrt((a - c) * (a - c) + 4.0 * b * b);
    const double largest = 0.5 * (a + c + disc);
    const double smallest = 0.5 * (a + c - disc);
    if (!(largest > 0.0) || smallest < 1e-10 * largest) {
      return kUnbounded;
    }
    return std::sqrt((a + c) / (a * c - b * b));
  }
  const auto crlb = positionCrlb(info, false);
  return crlb ? std::sqrt(crlb->trace()) : kUnbounded;
}

PlacementScore scoreFromInformation(const PlacementProblem& problem,
                                    const std::vector<Eigen::Matrix3d>& info) {
  std::vector<double> bounds(info.size());
  std::size_t unobservable = 0;
  double sum = 0.0;
  for (std::size_t t = 0; t < info.size(); ++t) {
    bounds[t] = pointBound(info[t], problem.advisor.planar);
    unobservable += std::isfinite(bounds[t]) ? 0 : 1;
    sum += bounds[t];
  }
  PlacementScore s;
  s.mean = sum / static_cast<double>(bounds.size());
  s.unobservable_fraction = static_cast<double>(unobservable) / static_cast<double>(bounds.size());
  // Nearest-rank percentile: the smallest bound at least 90 % of the targets reach.
  const auto rank =
      static_cast<std::ptrdiff_t>(std::ceil(0.9 * static_cast<double>(bounds.size()))) - 1;
  std::nth_element(bounds.begin(), bounds.begin() + rank, bounds.end());
  s.p90 = bounds[static_cast<std::size_t>(rank)];
  s.max = *std::max_element(bounds.begin(), bounds.end());
  switch (problem.region.objective) {
    case PlacementObjective::kMean:
      s.objective = s.mean;
      break;
    case PlacementObjective::kMax:
      s.objective = s.max;
      break;
    case PlacementObjective::kP90:
      s.objective = s.p90;
      break;
  }
  return s;
}

/// Adds candidate `c`'s information at every target to `sum`.
void addInformation(const std::vector<Eigen::Matrix3d>& table, int c, std::size_t targets,
                    std::vector<Eigen::Matrix3d>& sum) {
  const std::size_t base = static_cast<std::size_t>(c) * targets;
  for (std::size_t t = 0; t < targets; ++t) {
    sum[t] += table[base + t];
  }
}

bool spaced(const std::vector<MountCandidate>& candidates, const std::vector<int>& chosen, int c,
            double min_spacing) {
  return std::all_of(chosen.begin(), chosen.end(), [&](int o) {
    return o != c && (candidates[static_cast<std::size_t>(o)].position -
                      candidates[static_cast<std::size_t>(c)].position)
                             .norm() >= min_spacing - 1e-9;
  });
}

/// The modules' rms distance from their best-fit line in the xy-plane: the square root of
/// the smaller eigenvalue of their covariance.
double offLineRms(const std::vector<MountCandidate>& candidates, const std::vector<int>& chosen) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const int c : chosen) {
    mean += candidates[static_cast<std::size_t>(c)].position.head<2>();
  }
  mean /= static_cast<double>(chosen.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const int c : chosen) {
    const Eigen::Vector2d d = candidates[static_cast<std::size_t>(c)].position.head<2>() - mean;
    cov += d * d.transpose() / static_cast<double>(chosen.size());
  }
  const double half_trace = 0.5 * cov.trace();
  const double disc = std::sqrt(std::max(0.0, half_trace * half_trace - cov.determinant()));
  return std::sqrt(std::max(0.0, half_trace - disc));
}

/// The mounting rule the spacings do not cover: 3 or more modules not in one line.
bool spreadOffLine(const PlacementProblem& p, const std::vector<int>& modules) {
  return modules.size() < 3 || offLineRms(p.modules, modules) >= p.region.twr_min_off_line - 1e-12;
}

std::vector<Eigen::Matrix3d> sensorTable(const PlacementProblem& p,
                                         const std::vector<MountCandidate>& candidates,
                                         bool boards) {
  std::vector<Eigen::Matrix3d> table;
  table.reserve(candidates.size() * p.targets.size());
  for (const MountCandidate& c : candidates) {
    Layout one;
    if (boards) {
      AoaBoard b;
      b.position = c.position;
      b.orientation = Eigen::AngleAxisd(c.yaw, Eigen::Vector3d::UnitZ());
      b.kind = p.region.aoa_kind;
      b.field_of_view = p.region.aoa_field_of_view;
      one.aoa_boards.push_back(b);
    } else {
      TwrModule m;
      m.position = c.position;
      one.twr_modules.push_back(m);
    }
    for (const Eigen::Vector3d& target : p.targets) {
      table.push_back(fisherInformation(advisorObservations(one, target, p.advisor), target));
    }
  }
  return table;
}

/// Depth-first enumeration of every feasible placement for exhaustiveSearch, with the
/// information summed level by level so a leaf costs one addition per target.
class Enumerator {
 public:
  explicit Enumerator(const PlacementProblem& p)
      : p_(p),
        slots_(p.region.twr_count + p.region.aoa_count),
        sums_(static_cast<std::size_t>(slots_) + 1,
              std::vector<Eigen::Matrix3d>(p.targets.size(), Eigen::Matrix3d::Zero())) {}

  SearchResult run() {
    result_.score.objective = kUnbounded;
    result_.score.mean = kUnbounded;
    visit(0);
    return result_;
  }

 private:
  void visit(int level) {
    const std::size_t targets = p_.targets.size();
    if (level == slots_) {
      if (!spreadOffLine(p_, current_.modules)) {
        return;
      }
      ++result_.evaluations;
      const PlacementScore s = scoreFromInformation(p_, sums_[static_cast<std::size_t>(level)]);
      if (result_.evaluations == 1 || betterScore(s, result_.score)) {
        result_.score = s;
        result_.best = current_;
      }
      return;
    }
    const bool board = level >= p_.region.twr_count;
    const auto& candidates = board ? p_.boards : p_.modules;
    std::vector<int>& chosen = board ? current_.boards : current_.modules;
    const int remaining =
        (board ? p_.region.twr_count + p_.region.aoa_count : p_.region.twr_count) - level;
    const int first = chosen.empty() ? 0 : chosen.back() + 1;
    const double spacing = board ? p_.region.aoa_min_spacing : p_.region.twr_min_spacing;
    for (int c = first; c + remaining <= static_cast<int>(candidates.size()); ++c) {
      if (!spaced(candidates, chosen, c, spacing)) {
        continue;
      }
      auto& next = sums_[static_cast<std::size_t>(level) + 1];
      next = sums_[static_cast<std::size_t>(level)];
      addInformation(board ? p_.board_info : p_.module_info, c, targets, next);
      chosen.push_back(c);
      visit(level + 1);
      chosen.pop_back();
    }
  }

  const PlacementProblem& p_;
  int slots_;
  std::vector<std::vector<Eigen::Matrix3d>> sums_;
  Placement current_;
  SearchResult result_;
};

double choose(std::size_t n, int k) {
  double c = 1.0;
  for (int i = 0; i < k; ++i) {
    c = c * static_cast<double>(n - static_cast<std::size_t>(i)) / static_cast<double>(i + 1);
  }
  return c;
}

}  // namespace

PlacementProblem buildPlacementProblem(const MountingRegion& region, const AdvisorConfig& advisor) {
  region.validate();
  advisor.validate();
  PlacementProblem p;
  p.region = region;
  p.advisor = advisor;
  p.modules = moduleCandidates(region);
  p.boards = region.aoa_count > 0 ? boardCandidates(region) : std::vector<MountCandidate>{};
  require(p.modules.size() >= static_cast<std::size_t>(region.twr_count), "twr_modules.count",
          region.twr_count,
          "at most the " + std::to_string(p.modules.size()) +
              " module candidates (grid points inside the outline, outside keep_out)");
  require(p.boards.size() >= static_cast<std::size_t>(region.aoa_count), "aoa_boards.count",
          region.aoa_count,
          "at most the " + std::to_string(p.boards.size()) +
              " board candidates (points along the mount outline, outside keep_out)");
  p.targets = region.target.points();
  p.module_info = sensorTable(p, p.modules, false);
  p.board_info = sensorTable(p, p.boards, true);
  return p;
}

bool betterScore(const PlacementScore& a, const PlacementScore& b) {
  if (a.objective < b.objective - kTie) {
    return true;
  }
  const bool tied = a.objective == b.objective || std::abs(a.objective - b.objective) <= kTie;
  return tied && a.mean < b.mean - kTie;
}

PlacementScore scorePlacement(const PlacementProblem& problem, const Placement& placement) {
  std::vector<Eigen::Matrix3d> info(problem.targets.size(), Eigen::Matrix3d::Zero());
  for (const int m : placement.modules) {
    addInformation(problem.module_info, m, problem.targets.size(), info);
  }
  for (const int b : placement.boards) {
    addInformation(problem.board_info, b, problem.targets.size(), info);
  }
  return scoreFromInformation(problem, info);
}

bool feasiblePlacement(const PlacementProblem& problem, const Placement& placement) {
  const auto group_ok = [](const std::vector<MountCandidate>& candidates,
                           const std::vector<int>& chosen, int count, double spacing) {
    if (static_cast<int>(chosen.size()) != count) {
      return false;
    }
    std::vector<int> earlier;
    for (const int c : chosen) {
      if (c < 0 || c >= static_cast<int>(candidates.size()) ||
          !spaced(candidates, earlier, c, spacing)) {
        return false;
      }
      earlier.push_back(c);
    }
    return true;
  };
  const MountingRegion& r = problem.region;
  return group_ok(problem.modules, placement.modules, r.twr_count, r.twr_min_spacing) &&
         group_ok(problem.boards, placement.boards, r.aoa_count, r.aoa_min_spacing) &&
         spreadOffLine(problem, placement.modules);
}

double combinationCount(const PlacementProblem& problem) {
  return choose(problem.modules.size(), problem.region.twr_count) *
         choose(problem.boards.size(), problem.region.aoa_count);
}

SearchResult exhaustiveSearch(const PlacementProblem& problem, double max_combinations) {
  const double count = combinationCount(problem);
  if (count > max_combinations) {
    char text[400];
    std::snprintf(text, sizeof(text),
                  "exhaustive search refused: %.4g combinations (C(%zu module candidates, %d) x "
                  "C(%zu board candidates, %d)) exceed the limit of %.4g; use the greedy search "
                  "(--method greedy), fewer sensors or a coarser grid_spacing",
                  count, problem.modules.size(), problem.region.twr_count, problem.boards.size(),
                  problem.region.aoa_count, max_combinations);
    throw SearchTooLarge(text);
  }
  SearchResult r = Enumerator(problem).run();
  r.starts = 1;
  if (r.evaluations == 0) {
    throw ParamError("twr_modules.min_spacing", paramValueString(problem.region.twr_min_spacing),
                     "spacings the region can hold (no feasible placement)");
  }
  return r;
}

SearchResult greedySearch(const PlacementProblem& problem, const Placement& start) {
  require(feasiblePlacement(problem, start), "start", std::string("placement"),
          "a feasible placement (counts, indices, spacings)");
  SearchResult r;
  r.starts = 1;
  r.best = start;
  r.score = scorePlacement(problem, start);
  r.evaluations = 1;
  for (;;) {
    Placement best_move;
    PlacementScore best_score = r.score;
    bool improved = false;
    for (const bool board : {false, true}) {
      const auto& candidates = board ? problem.boards : problem.modules;
      for (std::size_t slot = 0; slot < (board ? r.best.boards : r.best.modules).size(); ++slot) {
        for (int c = 0; c < static_cast<int>(candidates.size()); ++c) {
          Placement next = r.best;
          std::vector<int>& group = board ? next.boards : next.modules;
          if (std::find(group.begin(), group.end(), c) != group.end()) {
            continue;
          }
          group[slot] = c;
          std::sort(group.begin(), group.end());
          if (!feasiblePlacement(problem, next)) {
            continue;
          }
          const PlacementScore s = scorePlacement(problem, next);
          ++r.evaluations;
          if (betterScore(s, best_score)) {
            best_score = s;
            best_move = next;
            improved = true;
          }
        }
      }
    }
    if (!improved) {
      return r;
    }
    r.best = best_move;
    r.score = best_score;
  }
}

Placement randomPlacement(const PlacementProblem& problem, std::mt19937_64& rng) {
  const MountingRegion& region = problem.region;
  const auto draw = [&](const std::vector<MountCandidate>& candidates, int count, double spacing,
                        std::vector<int>& chosen) {
    chosen.clear();
    for (int k = 0; k < count; ++k) {
      std::vector<int> free;
      for (int c = 0; c < static_cast<int>(candidates.size()); ++c) {
        if (spaced(candidates, chosen, c, spacing)) {
          free.push_back(c);
        }
      }
      if (free.empty()) {
        return false;
      }
      std::uniform_int_distribution<std::size_t> pick(0, free.size() - 1);
      chosen.push_back(free[pick(rng)]);
    }
    std::sort(chosen.begin(), chosen.end());
    return true;
  };
  Placement p;
  for (int attempt = 0; attempt < 1000; ++attempt) {
    if (draw(problem.modules, region.twr_count, region.twr_min_spacing, p.modules) &&
        draw(problem.boards, region.aoa_count, region.aoa_min_spacing, p.boards) &&
        spreadOffLine(problem, p.modules)) {
      return p;
    }
  }
  throw ParamError("twr_modules.min_spacing", paramValueString(region.twr_min_spacing),
                   "spacings the region can hold: 1000 random draws found no feasible placement "
                   "(min_spacing apart, min_off_line off one line)");
}

SearchResult greedyRestarts(const PlacementProblem& problem, int restarts, std::uint64_t seed) {
  require(restarts >= 1, "--restarts", restarts, "at least one start");
  std::mt19937_64 rng(seed);
  SearchResult best;
  for (int i = 0; i < restarts; ++i) {
    const SearchResult r = greedySearch(problem, randomPlacement(problem, rng));
    if (i == 0 || betterScore(r.score, best.score)) {
      best.best = r.best;
      best.score = r.score;
    }
    best.evaluations += r.evaluations;
  }
  best.starts = static_cast<std::size_t>(restarts);
  return best;
}

SearchResult randomSearch(const PlacementProblem& problem, int samples, std::uint64_t seed) {
  require(samples >= 1, "--samples", samples, "at least one sample");
  std::mt19937_64 rng(seed);
  SearchResult best;
  for (int i = 0; i < samples; ++i) {
    const Placement p = randomPlacement(problem, rng);
    const PlacementScore s = scorePlacement(problem, p);
    if (i == 0 || betterScore(s, best.score)) {
      best.best = p;
      best.score = s;
    }
  }
  best.evaluations = static_cast<std::size_t>(samples);
  best.starts = static_cast<std::size_t>(samples);
  return best;
}

MinimumSensorsResult minimumSensors(const MountingRegion& region, const AdvisorConfig& advisor,
                                    double limit, GrowSensors grow, bool greedy, int effort,
                                    std::uint64_t seed) {
  require(limit > 0.0, "--limit", limit, "a bound in metres > 0");
  MinimumSensorsResult out;
  const auto attempt = [&](int modules, int boards) -> std::optional<SearchResult> {
    MountingRegion r = region;
    r.twr_count = modules;
    r.aoa_count = boards;
    if (modules > 16 || boards > 16) {
      return std::nullopt;
    }
    try {
      const PlacementProblem p = buildPlacementProblem(r, advisor);
      SearchResult s = greedy ? greedyRestarts(p, effort, seed) : randomSearch(p, effort, seed);
      out.evaluations += s.evaluations;
      return s;
    } catch (const ParamError&) {
      return std::nullopt;  // more sensors than candidates, or than the spacing lets fit
    }
  };
  int modules = region.twr_count;
  int boards = region.aoa_count;
  std::optional<SearchResult> current = attempt(modules, boards);
  while (current && current->score.objective > limit) {
    std::optional<SearchResult> more_modules;
    std::optional<SearchResult> more_boards;
    if (grow != GrowSensors::kBoards) {
      more_modules = attempt(modules + 1, boards);
    }
    if (grow != GrowSensors::kModules) {
      more_boards = attempt(modules, boards + 1);
    }
    const bool take_boards =
        more_boards && (!more_modules || betterScore(more_boards->score, more_modules->score));
    if (!take_boards && !more_modules) {
      break;
    }
    current = take_boards ? more_boards : more_modules;
    (take_boards ? boards : modules) += 1;
  }
  if (current) {
    out.search = *current;
    out.reached = current->score.objective <= limit;
  }
  out.modules = modules;
  out.boards = boards;
  return out;
}

Layout placementLayout(const PlacementProblem& problem, const Placement& placement) {
  Layout layout;
  layout.target_anchor_id = problem.region.uwb_anchor_id;
  for (std::size_t i = 0; i < placement.modules.size(); ++i) {
    char id[32];
    std::snprintf(id, sizeof(id), "%04zu", i + 1);
    TwrModule m;
    m.id = id;
    m.frame_id = "uwb_" + m.id;
    m.position = problem.modules[static_cast<std::size_t>(placement.modules[i])].position;
    layout.twr_modules.push_back(m);
  }
  for (std::size_t i = 0; i < placement.boards.size(); ++i) {
    const MountCandidate& c = problem.boards[static_cast<std::size_t>(placement.boards[i])];
    AoaBoard b;
    b.id = "aoa" + std::to_string(i + 1);
    b.frame_id = "aoa_" + b.id;
    b.kind = problem.region.aoa_kind;
    b.position = c.position;
    b.orientation = Eigen::AngleAxisd(c.yaw, Eigen::Vector3d::UnitZ());
    b.field_of_view = problem.region.aoa_field_of_view;
    layout.aoa_boards.push_back(b);
  }
  layout.validate();
  return layout;
}

}  // namespace estimation
}  // namespace radio_follow
