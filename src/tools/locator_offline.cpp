// SPDX-License-Identifier: BSD-3-Clause
// locator_offline: replays the raw sensor messages of a bag through the locator library
// as fast as the CPU allows, without a ROS master. Writes the estimates (CSV) and, when
// the bag has the simulator's ground truth, error statistics overall, by direction and by
// distance, and the heading error and miss at the target by status (HEADING_ONLY too: a
// layout without ranges is judged on its direction); with --sweep, tries every combination of a grid of parameter values and ranks
// them. Usage: doc/offline_evaluation.md.
#include <yaml-cpp/yaml.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "radio_follow/common/command_line.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/yaml_params.hpp"
#include "radio_follow/ros/locator/locator_node.hpp"
#include "radio_follow/ros/replay/locator_replay.hpp"

namespace rf = radio_follow;

namespace {

struct Options {
  std::string bag;
  std::string layout;
  std::vector<std::string> params;
  std::string sweep;
  std::string out;
  std::string truth_topic = "ground_truth/target_relative";
  double rate = 0.0;  ///< 0: the parameter files' `rate`
};

rf::cli::CommandLine commandLine() {
  rf::cli::CommandLine cli(
      "locator_offline",
      "usage: locator_offline BAG --layout LAYOUT.yaml [--params LOCATOR.yaml]...\n"
      "         [--rate HZ] [--truth-topic TOPIC] [--out DIR] [--sweep GRID.yaml]\n",
      "Replays a bag's raw ranges, bearings and TDoA differences (any topics with UwbRanges,\n"
      "AoaBearing, TdoaMeasurements) through the locator library, as fast as the CPU allows,\n"
      "without a ROS master (doc/offline_evaluation.md). With a ground truth in the bag it\n"
      "prints the position error (overall, by direction, by distance) and the heading error\n"
      "by status.\n");
  namespace po = rf::cli::po;
  cli.options()("layout", po::value<std::string>()->value_name("FILE"),
                "the recorded robot's layout")(
      "params", po::value<std::vector<std::string>>()->value_name("FILE"),
      "locator parameters; repeat: later files override earlier keys (default: the "
      "locator's own defaults)")("rate", po::value<std::string>()->value_name("HZ"),
                                 "update rate (default: the files' rate)")(
      "truth-topic", po::value<std::string>()->value_name("TOPIC"),
      "PointStamped ground truth in the robot frame (default: ground_truth/target_relative, "
      "the simulator's)")("out", po::value<std::string>()->value_name("DIR"),
                          "write estimates.csv and summary.json (sweep.csv) there")(
      "sweep", po::value<std::string>()->value_name("GRID.yaml"),
      "try every combination of a grid of parameter values, ranked");
  cli.positional("bag", -1);
  return cli;
}

Options read(const rf::cli::po::variables_map& values) {
  using rf::cli::CommandLine;
  Options o;
  const std::vector<std::string> bags = CommandLine::texts(values, "bag");
  o.layout = CommandLine::text(values, "layout");
  if (bags.size() != 1 || o.layout.empty()) {
    throw rf::cli::UsageError(bags.size() > 1 ? "more than one bag given"
                                              : "a bag and --layout are required");
  }
  o.bag = bags.front();
  o.params = CommandLine::texts(values, "params");
  o.sweep = CommandLine::text(values, "sweep");
  o.out = CommandLine::text(values, "out");
  o.truth_topic = CommandLine::text(values, "truth-topic", o.truth_topic);
  if (values.count("rate")) {
    o.rate = rf::cli::number("--rate", CommandLine::text(values, "rate"), "a rate > 0 Hz",
                             [](double hz) { return hz > 0.0; });
  }
  return o;
}

Options parse(int argc, char** argv) {
  return commandLine().parse(argc, argv, read);
}

/// The parameter files merged in order (later files override earlier keys).
YAML::Node mergedParams(const std::vector<std::string>& files) {
  YAML::Node merged(YAML::NodeType::Map);
  for (const std::string& file : files) {
    const rf::YamlParams p = rf::YamlParams::fromFile(file);
    for (const auto& kv : p.root()) {
      merged[kv.first.as<std::string>()] = kv.second;
    }
  }
  return merged;
}

rf::LocatorNode::Params loadParams(const YAML::Node& yaml, const std::string& layout) {
  rf::LocatorNode::Params p;
  const rf::YamlParams source(yaml);
  p.load(source);
  source.requireAllKnown();  // a misspelt key in --params or --sweep is an error, as on a node
  p.layout_file = layout;
  p.validate();
  for (const std::string& line : p.locator.ignoredSettings()) {
    std::cerr << "locator_offline: warning: " << line << "\n";
  }
  return p;
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) {
    throw std::runtime_error("cannot write " + path);
  }
}

// The layout's sensors the bag has no message of, and the bag's sensors the layout does
// not name: a layout that matches none of the bag explains an empty replay.
void printSensorMatch(const rf::SensorMatch& match, const rf::Layout& layout) {
  const std::set<std::string>& heard = match.heard;          // layout IDs with a message
  const std::set<std::string>& strangers = match.strangers;  // IDs the layout does not know
  const rf::SensorTopics topics = rf::conventionalTopics(layout);
  std::vector<std::string> silent;
  for (std::size_t i = 0; i < layout.twr_modules.size(); ++i) {
    if (heard.count(layout.twr_modules[i].id) == 0) {
      silent.push_back(layout.twr_modules[i].id + " (" + topics.uwb[i] + ")");
    }
  }
  for (std::size_t i = 0; i < layout.aoa_boards.size(); ++i) {
    if (heard.count(layout.aoa_boards[i].id) == 0) {
      silent.push_back(layout.aoa_boards[i].id + " (" + topics.aoa[i] + ")");
    }
  }
  if (!silent.empty()) {
    std::cout << "layout sensors with no message in the bag:";
    for (const std::string& name : silent) {
      std::cout << " " << name;
    }
    std::cout << "\n";
  }
  if (!strangers.empty()) {
    std::cout << "sensors in the bag that the layout does not name (is --layout the recorded "
                 "robot's?):";
    for (const std::string& name : strangers) {
      std::cout << " " << name;
    }
    std::cout << "\n";
  }
}

/// The direction against the truth, by status: what a layout without ranges is judged
/// on (HEADING_ONLY has no position to compare), and what the robot steers by.
void printHeading(const rf::HeadingStatistics& h) {
  if (h.empty()) {
    return;
  }
  std::cout << "heading error (deg) and miss at the target (m, its distance from the "
               "robot's heading ray), median / p95:\n";
  const auto line = [&](const std::string& name, const std::string& status) {
    const rf::ErrorSummary e = h.headingError(status);
    const rf::ErrorSummary m = h.miss(status);
    std::cout << "  " << name << ": " << e.median << " / " << e.p95 << " deg, " << m.median
              << " / " << m.p95 << " m (" << e.count << ")\n";
  };
  line("all", "");
  for (const std::string& status : h.statuses()) {
    line(status, status);
  }
}

void printSummary(const rf::ReplayResult& r, const rf::BagData& bag, const std::string& odom_frame,
                  const std::string& truth_topic) {
  const rf::estimation::OdometryPlacement& placed = r.placement;
  if (odom_frame.empty()) {
    std::cout << "tracking in the robot frame (odom_frame \"\")\n";
  } else {
    std::cout << "tracking in " << odom_frame << ": " << placed.placed()
              << " messages placed with the bag's TF, " << placed.dropped() << " dropped (TF gap), "
              << placed.robotFrame() << " in the robot frame (no odometry)\n";
  }
  const rf::ErrorSummary all = r.statistics.overall();
  std::cout << "updates " << r.rows.size() << ", with a position " << r.availability * 100.0
            << " %, compared with the ground truth " << all.count << "\n";
  if (bag.truth.empty()) {
    std::cout << "no ground truth in the bag (no message on " << truth_topic
              << "): estimates only\n";
    return;
  }
  printHeading(r.heading);
  if (all.count == 0) {
    std::cout << "the bag has " << bag.truth.size() << " ground-truth points on " << truth_topic
              << ", but no estimate had a position to compare"
              << (r.heading.empty() ? "" : " (directions only: judged by their heading above)")
              << "\n";
    return;
  }
  std::cout << "error (m): mean " << all.mean << ", median " << all.median << ", p95 " << all.p95
            << ", max " << all.max << "\n"
            << "by direction (sector centre deg: median / p95 m, count):\n";
  for (std::size_t i = 0; i < rf::ErrorStatistics::kSectors; ++i) {
    const rf::ErrorSummary s = r.statistics.sector(i);
    std::cout << "  " << i * 45 << ": " << s.median << " / " << s.p95 << " (" << s.count << ")\n";
  }
  std::cout << "by distance (median / p95 m, count):\n";
  for (std::size_t i = 0; i <= rf::ErrorStatistics::kBandEdges.size(); ++i) {
    const rf::ErrorSummary s = r.statistics.band(i);
    std::cout << "  " << rf::ErrorStatistics::bandName(i) << ": " << s.median << " / " << s.p95
              << " (" << s.count << ")\n";
  }
}

int runSweep(const Options& o, const rf::BagData& bag, const rf::Layout& layout,
             const YAML::Node& base) {
  const rf::YamlParams grid = rf::YamlParams::fromFile(o.sweep);
  std::vector<std::pair<std::string, std::vector<YAML::Node>>> axes;
  for (const auto& kv : grid.root()) {
    const std::string key = kv.first.as<std::string>();
    if (!kv.second.IsSequence() || kv.second.size() == 0) {
      throw rf::ParamError("sweep." + key, YAML::Dump(kv.second), "a non-empty list of values");
    }
    std::vector<YAML::Node> values(kv.second.begin(), kv.second.end());
    axes.emplace_back(key, values);
  }
  if (axes.empty()) {
    throw rf::ParamError("sweep", "'" + o.sweep + "'", "a mapping of parameter -> [values]");
  }
  struct Run {
    std::string setting;
    rf::ErrorSummary error;
    double availability;
  };
  std::vector<Run> runs;
  std::vector<std::size_t> index(axes.size(), 0);
  while (true) {
    YAML::Node params = YAML::Clone(base);
    std::ostringstream setting;
    for (std::size_t a = 0; a < axes.size(); ++a) {
      params[axes[a].first] = axes[a].second[index[a]];
      setting << (a ? " " : "") << axes[a].first << "=" << YAML::Dump(axes[a].second[index[a]]);
    }
    const rf::LocatorNode::Params p = loadParams(params, o.layout);
    const rf::ReplayResult r = rf::replay(bag, layout, p, o.rate > 0 ? o.rate : p.rate);
    runs.push_back({setting.str(), r.statistics.overall(), r.availability});
    std::size_t a = 0;
    while (a < axes.size() && ++index[a] == axes[a].second.size()) {
      index[a++] = 0;
    }
    if (a == axes.size()) {
      break;
    }
  }
  // Best first: lowest 95th percentile, then median; runs without a truth last.
  std::stable_sort(runs.begin(), runs.end(), [](const Run& x, const Run& y) {
    const bool xv = x.error.count > 0, yv = y.error.count > 0;
    if (xv != yv) {
      return xv;
    }
    return x.error.p95 != y.error.p95 ? x.error.p95 < y.error.p95 : x.error.median < y.error.median;
  });
  std::ostringstream csv;
  csv << "rank,setting,median_m,p95_m,mean_m,max_m,compared,availability\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Run& r = runs[i];
    csv << i + 1 << ",\"" << r.setting << "\"," << r.error.median << "," << r.error.p95 << ","
        << r.error.mean << "," << r.error.max << "," << r.error.count << "," << r.availability
        << "\n";
  }
  std::cout << csv.str();
  if (!o.out.empty()) {
    writeFile(o.out + "/sweep.csv", csv.str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    const YAML::Node base = mergedParams(o.params);
    const rf::LocatorNode::Params params = loadParams(base, o.layout);
    const rf::Layout layout = rf::loadLayoutFile(o.layout, "--layout");
    if (!o.out.empty()) {
      std::filesystem::create_directories(o.out);
    }
    const rf::BagData bag = rf::loadBag(o.bag, o.truth_topic);
    if (!o.sweep.empty()) {
      return runSweep(o, bag, layout, base);
    }
    const double rate = o.rate > 0 ? o.rate : params.rate;
    const auto start = std::chrono::steady_clock::now();
    const rf::ReplayResult result = rf::replay(bag, layout, params, rate);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "bag " << o.bag << ": " << bag.duration() << " s, " << bag.entries.size()
              << " sensor messages, replayed in " << wall << " s ("
              << bag.duration() / std::max(wall, 1e-9) << " x real time)\n";
    printSensorMatch(result.sensors, layout);
    printSummary(result, bag, params.odom_frame, o.truth_topic);
    if (result.refused > 0) {
      std::cout << result.refused << " measurements refused (sensors not in the layout?)\n";
    }
    if (!o.out.empty()) {
      writeFile(o.out + "/estimates.csv", rf::toCsv(result));
      writeFile(o.out + "/summary.json", rf::summaryJson(result));
      std::cout << "wrote " << o.out << "/estimates.csv and summary.json\n";
    }
  } catch (const rf::ParamError& e) {
    std::cerr << "locator_offline: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "locator_offline: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
