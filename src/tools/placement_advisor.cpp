// SPDX-License-Identifier: BSD-3-Clause
// Sensor placement advisor: the Cramer-Rao bound of the target position over a grid
// around the robot for a layout YAML (the locator's format), a summary per ring and
// direction, and the thesis's placement guidelines; or, with --optimise, the search for
// the best layout in a mounting region (estimation/placement_search.hpp). ROS-free.
//
//   placement_advisor LAYOUT.yaml [--compare OTHER.yaml] [--extent M] [--resolution M]
//                     [--height M] [--3d] [--sectors N] [--weak-factor K]
//                     [--plot scripts/plot_placement.py] --out DIR
//   placement_advisor --optimise REGION.yaml [--method exhaustive|greedy|random|all]
//                     [--objective mean|p90|max|all] [--modules N] [--boards N]
//                     [--restarts N] [--samples N] [--runs N] [--seed S]
//                     [--max-combinations N] [--limit M [--grow modules|boards|both]]
//                     [--compare REFERENCE.yaml] ... --out DIR
//
// Writes DIR/<layout>_map.csv and DIR/<layout>_summary.json per layout and prints the
// summary; --plot runs the given plot script on them (DIR/<layout>[_vs_<other>].png).
// --optimise prints the searches as a Markdown table, writes the best layout as
// DIR/<region>_optimised.yaml and then maps it (and the reference) as above.
#include "radio_follow/estimation/placement_advisor.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "placement_advisor/options.hpp"
#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/error_statistics.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/config/layout_writer.hpp"
#include "radio_follow/estimation/placement_search.hpp"

namespace rf = radio_follow;
namespace fs = std::filesystem;
using rf::jsonNumber;
using rf::jsonString;

namespace {

namespace est = rf::estimation;
using rf::placement_advisor::OptimiseOptions;
using rf::placement_advisor::Options;
using rf::placement_advisor::parse;

struct Evaluated {
  std::string name;
  rf::Layout layout;
  rf::estimation::PlacementSummary summary;
};

std::string csvNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return std::isfinite(value) ? buffer : "inf";
}

void writeMap(const fs::path& path, const rf::estimation::BoundMap& map) {
  std::ofstream out(path);
  out << "x,y,distance,direction_deg,rms_bound,worst_axis_bound,bearings,observable\n";
  for (std::size_t iy = 0; iy < map.coordinates.size(); ++iy) {
    for (std::size_t ix = 0; ix < map.coordinates.size(); ++ix) {
      const double x = map.coordinates[ix];
      const double y = map.coordinates[iy];
      const rf::estimation::PointBound& b = map.at(ix, iy);
      out << csvNumber(x) << ',' << csvNumber(y) << ',' << csvNumber(std::hypot(x, y)) << ','
          << csvNumber(rf::rad2deg(std::atan2(y, x))) << ',' << csvNumber(b.rms) << ','
          << csvNumber(b.worst_axis) << ',' << b.bearings << ',' << (b.observable ? 1 : 0) << '\n';
    }
  }
  if (!out) {
    throw std::runtime_error("cannot write " + path.string());
  }
}

void writeSummary(const fs::path& path, const Evaluated& e,
                  const rf::estimation::AdvisorConfig& config, const std::string& csv_name) {
  std::ofstream out(path);
  out << "{\n  \"layout\": " << jsonString(e.name) << ",\n  \"map_csv\": " << jsonString(csv_name)
      << ",\n  \"extent\": " << jsonNumber(config.extent)
      << ", \"resolution\": " << jsonNumber(config.resolution)
      << ", \"height\": " << jsonNumber(config.target_height)
      << ", \"planar\": " << (config.planar ? "true" : "false")
      << ", \"weak_factor\": " << jsonNumber(config.weak_factor) << ",\n  \"rings\": [";
  for (std::size_t i = 0; i < e.summary.rings.size(); ++i) {
    const auto& r = e.summary.rings[i];
    out << (i ? ", " : "") << "{\"radius\": " << jsonNumber(r.radius)
        << ", \"median\": " << jsonNumber(r.median) << ", \"worst\": " << jsonNumber(r.worst)
        << ", \"unobservable_fraction\": " << jsonNumber(r.unobservable_fraction) << "}";
  }
  out << "],\n  \"sectors\": [";
  for (std::size_t i = 0; i < e.summary.sectors.size(); ++i) {
    const auto& s = e.summary.sectors[i];
    out << (i ? ", " : "") << "{\"centre_deg\": " << jsonNumber(s.centre_deg)
        << ", \"worst_ratio\": " << jsonNumber(s.worst_ratio)
        << ", \"weak\": " << (s.weak ? "true" : "false") << "}";
  }
  out << "],\n  \"warnings\": [";
  for (std::size_t i = 0; i < e.summary.warnings.size(); ++i) {
    out << (i ? ",\n    " : "\n    ") << jsonString(e.summary.warnings[i]);
  }
  out << "],\n  \"twr_modules\": [";
  for (std::size_t i = 0; i < e.layout.twr_modules.size(); ++i) {
    const auto& m = e.layout.twr_modules[i];
    out << (i ? ", " : "") << "{\"id\": " << jsonString(m.id) << ", \"position\": ["
        << jsonNumber(m.position.x()) << ", " << jsonNumber(m.position.y()) << ", "
        << jsonNumber(m.position.z()) << "]}";
  }
  out << "],\n  \"aoa_boards\": [";
  for (std::size_t i = 0; i < e.layout.aoa_boards.size(); ++i) {
    const auto& b = e.layout.aoa_boards[i];
    const Eigen::Vector3d axis = b.orientation * Eigen::Vector3d::UnitX();
    out << (i ? ", " : "") << "{\"id\": " << jsonString(b.id) << ", \"position\": ["
        << jsonNumber(b.position.x()) << ", " << jsonNumber(b.position.y()) << ", "
        << jsonNumber(b.position.z())
        << "], \"yaw_deg\": " << jsonNumber(rf::rad2deg(std::atan2(axis.y(), axis.x())))
        << ", \"field_of_view_deg\": " << jsonNumber(rf::rad2deg(b.field_of_view)) << "}";
  }
  out << "]\n}\n";
  if (!out) {
    throw std::runtime_error("cannot write " + path.string());
  }
}

std::string cell(double value) {
  char buffer[32];
  if (std::isnan(value)) {
    return "n/a";
  }
  if (!std::isfinite(value)) {
    return "unobs.";
  }
  std::snprintf(buffer, sizeof(buffer), "%.3f", value);
  return buffer;
}

void print(const Evaluated& e, const rf::estimation::AdvisorConfig& config) {
  std::printf("== %s (%s bound, target at %.2f m height)\n", e.name.c_str(),
              config.planar ? "2D" : "3D", config.target_height);
  std::printf("  ring    median sqrt(tr CRLB)   worst    unobservable\n");
  for (const auto& r : e.summary.rings) {
    std::printf("  %4.1f m  %8s m            %8s m  %5.1f %%\n", r.radius, cell(r.median).c_str(),
                cell(r.worst).c_str(), 100.0 * r.unobservable_fraction);
  }
  std::string weak;
  for (const auto& s : e.summary.sectors) {
    if (s.weak) {
      char buffer[64];
      const std::string ratio =
          std::isfinite(s.worst_ratio) ? cell(s.worst_ratio) + " x median" : "unobservable";
      std::snprintf(buffer, sizeof(buffer), " %+.1f deg (%s)", s.centre_deg, ratio.c_str());
      weak += buffer;
    }
  }
  std::printf("  weak sectors (> %.1f x ring median):%s\n", config.weak_factor,
              weak.empty() ? " none" : weak.c_str());
  for (const auto& w : e.summary.warnings) {
    std::printf("  WARNING: %s\n", w.c_str());
  }
}

Evaluated evaluate(const std::string& path, const Options& opt, const fs::path& out) {
  Evaluated e;
  e.name = fs::path(path).stem().string();
  e.layout = rf::loadLayoutFile(path, "--layout");
  e.summary = rf::estimation::summarize(e.layout, opt.config);
  const std::string csv = e.name + "_map.csv";
  writeMap(out / csv, rf::estimation::computeMap(e.layout, opt.config));
  writeSummary(out / (e.name + "_summary.json"), e, opt.config, csv);
  print(e, opt.config);
  return e;
}

/// One search of --optimise and what it cost.
struct SearchRow {
  std::string objective;
  std::string method;
  std::uint64_t seed = 0;
  est::SearchResult result;
  double seconds = 0.0;
  bool refused = false;
};

/// "(x, y)" per module, then "(x, y) yaw" per board, in the table's sensors column.
std::string sensorList(const est::PlacementProblem& p, const est::Placement& placement) {
  std::string text;
  char buffer[64];
  for (const int m : placement.modules) {
    const auto& c = p.modules[static_cast<std::size_t>(m)];
    std::snprintf(buffer, sizeof(buffer), "M(%.2f, %.2f) ", c.position.x(), c.position.y());
    text += buffer;
  }
  for (const int b : placement.boards) {
    const auto& c = p.boards[static_cast<std::size_t>(b)];
    const double yaw = std::round(rf::rad2deg(c.yaw));
    std::snprintf(buffer, sizeof(buffer), "B(%.2f, %.2f)%+.0f ", c.position.x(), c.position.y(),
                  yaw == 0.0 ? 0.0 : yaw);  // no "-0"
    text += buffer;
  }
  return text.empty() ? text : text.substr(0, text.size() - 1);
}

SearchRow runSearch(const est::PlacementProblem& problem, const std::string& method,
                    std::uint64_t seed, const OptimiseOptions& o) {
  SearchRow row;
  row.method = method;
  row.seed = seed;
  row.objective = est::toString(problem.region.objective);
  const auto start = std::chrono::steady_clock::now();
  if (method == "exhaustive") {
    row.result = est::exhaustiveSearch(problem, o.max_combinations);
  } else if (method == "greedy") {
    row.result = est::greedyRestarts(problem, o.restarts, seed);
  } else {
    row.result = est::randomSearch(problem, o.samples, seed);
  }
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return row;
}

void printRows(const std::vector<SearchRow>& rows, const est::PlacementProblem& problem) {
  std::printf(
      "\n| optimised for | method | seed | starts | mean (m) | p90 (m) | max (m) | evaluations "
      "| time (ms) | time / first row | sensors "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  const SearchRow* baseline = nullptr;
  for (const SearchRow& row : rows) {
    if (baseline == nullptr || baseline->objective != row.objective) {
      baseline = row.refused ? nullptr : &row;
    }
    if (row.refused) {
      std::printf("| %s | %s | - | - | refused | | | | | | |\n", row.objective.c_str(),
                  row.method.c_str());
      continue;
    }
    const auto& r = row.result;
    const std::string seed = row.method == "exhaustive" ? "-" : std::to_string(row.seed);
    std::printf("| %s | %s | %s | %zu | %s | %s | %s | %zu | %.1f | %s | %s |\n",
                row.objective.c_str(), row.method.c_str(), seed.c_str(), r.starts,
                cell(r.score.mean).c_str(), cell(r.score.p90).c_str(), cell(r.score.max).c_str(),
                r.evaluations, 1e3 * row.seconds,
                baseline ? cell(row.seconds / baseline->seconds).c_str() : "n/a",
                sensorList(problem, r.best).c_str());
  }
  std::printf("\n");
}

/// The layout --optimise writes and the line saying how it was found.
struct Chosen {
  est::PlacementProblem problem;  ///< with the counts of the placement
  est::Placement placement;
  std::string how;
};

/// The method table (Tables 5.1 and the search comparison): every objective x method x run.
Chosen searchTable(est::PlacementProblem problem, const OptimiseOptions& o) {
  const std::string own = est::toString(problem.region.objective);
  const std::vector<std::string> objectives =
      o.objectives.empty() ? std::vector<std::string>{own} : o.objectives;
  std::vector<SearchRow> rows;
  for (const std::string& objective : objectives) {
    problem.region.objective = est::parsePlacementObjective(objective, "--objective");
    for (const std::string& method : o.methods) {
      for (int run = 0; run < (method == "exhaustive" ? 1 : o.runs); ++run) {
        try {
          rows.push_back(runSearch(problem, method, o.seed + static_cast<std::uint64_t>(run), o));
        } catch (const est::SearchTooLarge& e) {
          if (o.methods.size() == 1) {
            throw;
          }
          std::fprintf(stderr, "placement_advisor: %s\n", e.what());
          rows.push_back({objective, method, 0, {}, 0.0, true});
        }
      }
    }
  }
  printRows(rows, problem);
  // The layout written: the best for the region's objective (or the first one searched).
  const bool listed = std::find(objectives.begin(), objectives.end(), own) != objectives.end();
  const std::string wanted = listed ? own : objectives.front();
  const SearchRow* best = nullptr;
  for (const SearchRow& row : rows) {
    if (!row.refused && row.objective == wanted &&
        (best == nullptr || est::betterScore(row.result.score, best->result.score))) {
      best = &row;
    }
  }
  problem.region.objective = est::parsePlacementObjective(wanted, "--objective");
  char how[200];
  std::snprintf(how, sizeof(how), "%s search, %s of sqrt(trace CRLB) = %.4f m",
                best->method.c_str(), wanted.c_str(), best->result.score.objective);
  return {problem, best->result.best, how};
}

/// --limit (Tables 5.2 and 5.3): the fewest sensors reaching the limit, one row per run.
Chosen limitTable(const est::PlacementProblem& problem, const OptimiseOptions& o) {
  const bool greedy = o.methods.front() == "greedy";
  rf::require(o.methods.size() == 1 && o.methods.front() != "exhaustive", "--method",
              o.methods.front(), "greedy or random with --limit");
  std::printf(
      "\n| run | seed | grow | modules | boards | total | reached | mean (m) | p90 (m) | max (m) "
      "| evaluations | time (ms) | sensors "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::optional<Chosen> chosen;
  Chosen last;
  int fewest = 0;
  double best_objective = 0.0;
  for (int run = 0; run < o.runs; ++run) {
    const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(run);
    const auto start = std::chrono::steady_clock::now();
    const est::MinimumSensorsResult r =
        est::minimumSensors(problem.region, problem.advisor, *o.limit, o.grow, greedy,
                            greedy ? o.restarts : o.samples, seed);
    const double ms =
        1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    est::MountingRegion region = problem.region;
    region.twr_count = r.modules;
    region.aoa_count = r.boards;
    const est::PlacementProblem sized = est::buildPlacementProblem(region, problem.advisor);
    const auto& s = r.search.score;
    std::printf("| %d | %llu | %s | %d | %d | %d | %s | %s | %s | %s | %zu | %.1f | %s |\n",
                run + 1, static_cast<unsigned long long>(seed), o.grow_text.c_str(), r.modules,
                r.boards, r.modules + r.boards, r.reached ? "yes" : "no", cell(s.mean).c_str(),
                cell(s.p90).c_str(), cell(s.max).c_str(), r.evaluations, ms,
                sensorList(sized, r.search.best).c_str());
    const int total = r.modules + r.boards;
    last = Chosen{
        sized, r.search.best,
        "limit not reached: " + est::toString(region.objective) + " = " + cell(s.objective) + " m"};
    if (r.reached &&
        (!chosen || total < fewest || (total == fewest && s.objective < best_objective))) {
      char how[200];
      std::snprintf(how, sizeof(how),
                    "fewest sensors with %s <= %.3f m: %s of sqrt(trace CRLB) = %.4f m",
                    est::toString(region.objective).c_str(), *o.limit,
                    est::toString(region.objective).c_str(), s.objective);
      chosen = Chosen{sized, r.search.best, how};
      fewest = total;
      best_objective = s.objective;
    }
  }
  std::printf("\n");
  if (!chosen) {
    // Still a layout to map: the last run's, with the header saying the limit was missed.
    std::printf("== no run reached the limit: the layout written is the last run's\n");
    chosen = last;
  }
  return *chosen;
}

/// --optimise: runs the searches, prints them, writes the best layout and returns its path.
std::string optimise(Options& opt, const fs::path& out) {
  const OptimiseOptions& o = *opt.optimise;
  est::MountingRegion region = est::loadMountingRegionFile(o.region);
  region.twr_count = o.modules.value_or(region.twr_count);
  region.aoa_count = o.boards.value_or(region.aoa_count);
  if (o.objectives.size() == 1) {
    region.objective = est::parsePlacementObjective(o.objectives.front(), "--objective");
  }
  rf::require(!o.limit || o.objectives.size() <= 1, "--objective", std::string("all"),
              "one objective with --limit");
  opt.config.target_height = region.target.height;  // the maps show the searched height
  const est::PlacementProblem problem = est::buildPlacementProblem(region, opt.config);
  std::printf(
      "== optimise %s: %d TWR modules among %zu candidates, %d AoA boards among %zu, "
      "%zu target points (%s bound), %.4g combinations\n",
      region.name.c_str(), region.twr_count, problem.modules.size(), region.aoa_count,
      problem.boards.size(), problem.targets.size(), opt.config.planar ? "2D" : "3D",
      est::combinationCount(problem));
  const Chosen chosen = o.limit ? limitTable(problem, o) : searchTable(problem, o);
  const rf::Layout layout = est::placementLayout(chosen.problem, chosen.placement);
  const fs::path path = out / (region.name + "_optimised.yaml");
  std::ofstream file(path);
  file << rf::writeLayout(
      layout, {"Written by placement_advisor --optimise " + o.region + ":",
               chosen.how + " over " + std::to_string(problem.targets.size()) +
                   " target points (doc/placement_advisor.md).",
               "Module IDs 0001.. are placeholders for your modules' IDs; the calibrations are",
               "identity until calibrate_layout fits them (doc/calibration.md)."});
  if (!file) {
    throw std::runtime_error("cannot write " + path.string());
  }
  std::printf("== wrote %s\n", path.string().c_str());
  return path.string();
}

}  // namespace

int main(int argc, char** argv) {
  Options opt = parse(argc, argv);
  try {
    const fs::path out(opt.out);
    fs::create_directories(out);
    if (opt.optimise) {
      opt.layout = optimise(opt, out);
    }
    const Evaluated first = evaluate(opt.layout, opt, out);
    std::string plot_args = "'" + (out / (first.name + "_summary.json")).string() + "'";
    std::string png = first.name;
    if (opt.compare) {
      if (fs::path(*opt.compare).stem().string() == first.name) {
        throw rf::ParamError("--compare", rf::paramValueString(*opt.compare),
                             "a layout file whose name differs from the first one's");
      }
      const Evaluated second = evaluate(*opt.compare, opt, out);
      std::printf("== %s / %s median bound ratio:", second.name.c_str(), first.name.c_str());
      for (std::size_t i = 0; i < first.summary.rings.size(); ++i) {
        std::printf(" %.1f m: %s", first.summary.rings[i].radius,
                    cell(second.summary.rings[i].median / first.summary.rings[i].median).c_str());
      }
      std::printf("\n");
      plot_args += " '" + (out / (second.name + "_summary.json")).string() + "'";
      png += "_vs_" + second.name;
    }
    if (opt.plot_script) {
      const std::string command = "python3 '" + *opt.plot_script + "' " + plot_args + " --out '" +
                                  (out / (png + ".png")).string() + "'";
      if (std::system(command.c_str()) != 0) {
        std::fprintf(stderr, "placement_advisor: plotting failed: %s\n", command.c_str());
        return 1;
      }
    }
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "placement_advisor: %s\n", ex.what());
    return 1;
  }
  return 0;
}
