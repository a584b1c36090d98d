// SPDX-License-Identifier: BSD-3-Clause
// calibrate_layout: fits every UWB module's range polynomial and every AoA board's yaw
// offset from a bag with a reference (a ground-truth topic, or tape-measured points the
// person stood at) and writes the layout with them. No ROS master. Usage:
// doc/deployment.md ("6. Calibrate the ranges and the boards' yaw").
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/command_line.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/yaml_keys.hpp"
#include "radio_follow/config/layout_writer.hpp"
#include "radio_follow/ros/replay/calibration_bag.hpp"

namespace rf = radio_follow;
namespace est = radio_follow::estimation;

namespace {

struct Options {
  std::string bag;
  std::string layout;
  std::string out;
  std::string truth_topic;
  std::string points;
  int degree = 1;
  double max_gap = 0.1;
  std::size_t min_samples = 30;
  std::vector<std::string> uwb_topics;
  std::vector<std::string> aoa_topics;
  bool aoa = true;
};

rf::cli::CommandLine commandLine() {
  rf::cli::CommandLine cli(
      "calibrate_layout",
      "usage: calibrate_layout --bag BAG --layout LAYOUT.yaml --out CALIBRATED.yaml\n"
      "         (--truth-topic TOPIC | --points POINTS.yaml) [--degree N] [--max-gap S]\n"
      "         [--min-samples N] [--uwb-topics T1,T2,...] [--aoa-topics T1,...] [--no-aoa]\n",
      "Fits each UWB module's range calibration polynomial and each AoA board's yaw offset\n"
      "from a bag and writes the layout with the new `calibration` and `rpy_deg` yaw.\n"
      "Prints one row per module and board: samples used and rejected (outliers: NLOS,\n"
      "reflections), RMS error before and after, the coefficients or the offset. A sensor\n"
      "that cannot be fitted keeps its old value. Exit 0 when at least one sensor was\n"
      "fitted and the file written, 1 when none could be (or the bag cannot be used),\n"
      "2 on bad flags or a bad layout / points file.\n");
  namespace po = rf::cli::po;
  const auto text = [](const char* name) { return po::value<std::string>()->value_name(name); };
  cli.options()("bag", text("BAG"), "the recording (raw driver topics and the reference)")(
      "layout", text("FILE"), "the robot's layout (module and board positions, old calibration)")(
      "out", text("FILE"),
      "the calibrated layout to write; everything but `calibration` and `rpy_deg` is kept, "
      "key order and quoting too, COMMENTS ARE NOT")(
      "truth-topic", text("T"),
      "reference: the tag's position in the layout's fixed frame, geometry_msgs/PointStamped "
      "(the simulator's ground_truth/target_relative), PoseStamped or nav_msgs/Odometry, "
      "interpolated to each measurement's stamp")(
      "points", text("FILE"),
      "reference: tape-measured points, YAML `points: [{position: [x, y, z], from: s, until: "
      "s}, ...]` (fixed frame, m; seconds from the bag's start); measurements outside every "
      "window are ignored")("degree", text("N"),
                            "range polynomial degree, 0 (offset) to 3; default 1")(
      "max-gap", text("S"),
      "with --truth-topic: drop a measurement farther than S seconds from any reference "
      "sample; default 0.1")("min-samples", text("N"),
                             "fewer paired samples keep a sensor's old value; default 30")(
      "uwb-topics", text("LIST"), "UwbRanges topics; default uwb/<module id>/ranges per module")(
      "aoa-topics", text("LIST"), "AoaBearing topics; default aoa/<board id>/bearing per board")(
      "no-aoa", po::bool_switch(), "fit the modules only; boards keep their rpy_deg");
  return cli;
}

std::vector<std::string> splitList(const std::string& flag, const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (item.empty()) {
      throw rf::cli::UsageError(flag + " '" + text +
                                "': expected topics separated by commas, none empty");
    }
    items.push_back(item);
  }
  if (items.empty()) {
    throw rf::cli::UsageError(flag + " '" + text + "': expected at least one topic");
  }
  return items;
}

Options read(const rf::cli::po::variables_map& values) {
  using rf::cli::CommandLine;
  Options o;
  o.bag = CommandLine::text(values, "bag");
  o.layout = CommandLine::text(values, "layout");
  o.out = CommandLine::text(values, "out");
  o.truth_topic = CommandLine::text(values, "truth-topic");
  o.points = CommandLine::text(values, "points");
  o.aoa = !values["no-aoa"].as<bool>();
  if (values.count("degree")) {
    o.degree = static_cast<int>(rf::cli::wholeNumber(
        "--degree", CommandLine::text(values, "degree"), 0, 3, "a whole number from 0 to 3"));
  }
  if (values.count("max-gap")) {
    o.max_gap = rf::cli::number("--max-gap", CommandLine::text(values, "max-gap"), "seconds > 0",
                                [](double s) { return s > 0.0; });
  }
  if (values.count("min-samples")) {
    o.min_samples = static_cast<std::size_t>(rf::cli::wholeNumber(
        "--min-samples", CommandLine::text(values, "min-samples"), 5, 1e9, "a whole number >= 5"));
  }
  if (values.count("uwb-topics")) {
    o.uwb_topics = splitList("--uwb-topics", CommandLine::text(values, "uwb-topics"));
  }
  if (values.count("aoa-topics")) {
    o.aoa_topics = splitList("--aoa-topics", CommandLine::text(values, "aoa-topics"));
  }
  if (o.bag.empty() || o.layout.empty() || o.out.empty()) {
    throw rf::cli::UsageError("--bag, --layout and --out are required");
  }
  if (o.truth_topic.empty() == o.points.empty()) {
    throw rf::cli::UsageError("give exactly one reference: --truth-topic TOPIC or --points FILE");
  }
  if (!o.aoa && !o.aoa_topics.empty()) {
    throw rf::cli::UsageError("--aoa-topics with --no-aoa: choose one");
  }
  return o;
}

Options parse(int argc, char** argv) {
  return commandLine().parse(argc, argv, read);
}

std::string coefficients(const std::vector<double>& c) {
  std::ostringstream out;
  out.precision(5);
  out << "[";
  for (std::size_t k = 0; k < c.size(); ++k) {
    out << (k ? ", " : "") << c[k];
  }
  out << "]";
  return out.str();
}

/// The default topics are a convention, not a promise: a module whose topic the bag
/// lacks is reported in its row; topics given on the command line must all be there, and
/// a bag without any of them is refused with what it does hold.
void checkTopics(const Options& o, const rf::CalibrationBag& bag, const std::string& bag_path) {
  std::size_t sensor_messages = 0;
  for (const auto& kv : bag.messages) {
    sensor_messages += kv.second;
  }
  auto require_present = [&](const std::vector<std::string>& given, const std::string& type) {
    for (const std::string& t : given) {
      if (bag.messages.at(t) == 0) {
        throw std::runtime_error("bag '" + bag_path + "' has no message on " + t + " (" + type +
                                 " topics in it: " + rf::topicsOfType(bag, type) + ")");
      }
    }
  };
  require_present(o.uwb_topics, "radio_follow/UwbRanges");
  require_present(o.aoa_topics, "radio_follow/AoaBearing");
  if (sensor_messages == 0) {
    throw std::runtime_error("bag '" + bag_path +
                             "' has none of the layout's sensor topics (UwbRanges topics in it: " +
                             rf::topicsOfType(bag, "radio_follow/UwbRanges") +
                             "; AoaBearing: " + rf::topicsOfType(bag, "radio_follow/AoaBearing") +
                             "): name them with --uwb-topics / --aoa-topics");
  }
}

/// Why sensor `i` of `count` was not fitted: with one topic per sensor (the layout's
/// convention, or as many given), a silent topic says more than "0 samples".
template <typename Calibration>
std::string whyNotFitted(const Calibration& sensor, std::size_t i, std::size_t count,
                         const std::vector<std::string>& topics, const rf::CalibrationBag& bag) {
  if (topics.size() == count && bag.messages.at(topics[i]) == 0) {
    return "no message on " + topics[i];
  }
  return sensor.error;
}

void printTable(const est::LayoutCalibration& c, const rf::Layout& layout,
                const rf::CalibrationTopics& topics, const rf::CalibrationBag& bag) {
  std::printf("%-10s %7s %8s %11s %10s  %s\n", "module", "used", "rejected", "rms before",
              "rms after", "calibration (c0, c1, ...)");
  for (std::size_t i = 0; i < c.modules.size(); ++i) {
    const auto& m = c.modules[i];
    if (m.fit) {
      std::printf("%-10s %7zu %8zu %9.3f m %8.3f m  %s\n", m.id.c_str(), m.fit->used,
                  m.fit->rejected, m.fit->rms_before, m.fit->rms_after,
                  coefficients(m.fit->coefficients).c_str());
      continue;
    }
    std::printf("%-10s not fitted, keeps %s: %s\n", m.id.c_str(),
                coefficients(layout.twr_modules[i].calibration).c_str(),
                whyNotFitted(m, i, c.modules.size(), topics.uwb, bag).c_str());
  }
  if (c.boards.empty()) {
    return;
  }
  std::printf("\n%-10s %7s %8s %11s %10s  %-22s %s\n", "board", "used", "rejected", "rms before",
              "rms after", "yaw: mounting + bias", "elevation bias (elevation_offset_deg)");
  for (std::size_t i = 0; i < c.boards.size(); ++i) {
    const auto& b = c.boards[i];
    const auto& e = c.elevations[i];
    if (b.fit) {
      std::printf("%-10s %7zu %8zu %7.2f deg %6.2f deg  %+9.2f deg (rpy_deg) ", b.id.c_str(),
                  b.fit->used, b.fit->rejected, rf::rad2deg(b.fit->rms_before),
                  rf::rad2deg(b.fit->residual_sigma), rf::rad2deg(b.fit->yaw_offset));
      if (e.fit) {
        std::printf("%+.2f deg\n", rf::rad2deg(e.fit->elevation_offset));
      } else {
        std::printf("not fitted: %s\n", e.error.c_str());
      }
      continue;
    }
    std::printf("%-10s not fitted, keeps its rpy_deg: %s\n", b.id.c_str(),
                whyNotFitted(b, i, c.boards.size(), topics.aoa, bag).c_str());
  }
}

int run(const Options& o) {
  const std::string layout_text =
      rf::readConfigFile(o.layout, "layout", "a readable layout YAML file");
  const rf::Layout layout = rf::parseLayout(layout_text, o.layout);
  const rf::SensorTopics conventional = rf::conventionalTopics(layout);
  rf::CalibrationTopics topics;
  topics.uwb = o.uwb_topics.empty() ? conventional.uwb : o.uwb_topics;
  topics.aoa = !o.aoa ? std::vector<std::string>{}
                      : (o.aoa_topics.empty() ? conventional.aoa : o.aoa_topics);
  topics.truth = o.truth_topic;
  // The points file is checked before the bag is read: its mistakes are quicker to fix.
  const std::vector<est::TapePoint> points =
      o.points.empty() ? std::vector<est::TapePoint>{} : est::loadTapePointsFile(o.points);

  const rf::CalibrationBag bag = rf::loadCalibrationBag(o.bag, layout, topics);
  checkTopics(o, bag, o.bag);
  if (!o.truth_topic.empty() && bag.truth.empty()) {
    throw std::runtime_error("bag '" + o.bag + "': no message on " + o.truth_topic);
  }
  const est::CalibrationReference reference =
      o.points.empty() ? est::CalibrationReference::fromTrack(bag.truth, o.max_gap)
                       : est::CalibrationReference::fromPoints(points);
  const est::CalibrationSamples samples =
      est::pairWithReference(bag.measurements, layout, reference);
  std::printf("bag %s: %.1f s, %zu ranges and bearings of the target", o.bag.c_str(), bag.duration,
              bag.measurements.size());
  if (reference.isTrack()) {
    std::printf(", %zu reference samples; %zu measurements dropped (no reference within %.3g s)",
                bag.truth.size(), samples.gap_dropped, o.max_gap);
  } else {
    std::printf(", %zu tape points; %zu measurements outside every window", points.size(),
                samples.outside_windows);
  }
  std::printf(
      ", %zu bearings outside the board's field of view, %zu of unknown sensors, %zu "
      "not finite\n\n",
      samples.outside_view, samples.unknown_sensor, samples.non_finite);

  const est::LayoutCalibration c =
      est::fitLayoutCalibration(samples, layout, o.degree, o.min_samples, o.aoa);
  printTable(c, layout, topics, bag);
  if (c.fitted() == 0) {
    std::cerr << "calibrate_layout: nothing could be fitted; " << o.out << " not written\n";
    return 1;
  }
  rf::LayoutCalibrationUpdate update;
  for (const auto& m : c.modules) {
    if (m.fit) {
      update.range_calibration[m.id] = m.fit->coefficients;
    }
  }
  for (const auto& b : c.boards) {
    if (b.fit) {
      update.yaw_offset[b.id] = b.fit->yaw_offset;
    }
  }
  for (const auto& e : c.elevations) {
    if (e.fit) {
      update.elevation_offset[e.id] = e.fit->elevation_offset;
    }
  }
  const std::string written = rf::writeCalibratedLayout(
      layout_text, o.layout, update,
      {"Calibrated by calibrate_layout from " + o.layout + " and the bag " + o.bag + " (" +
           (o.points.empty() ? "ground truth " + o.truth_topic : "tape points " + o.points) +
           ", degree " + std::to_string(o.degree) + ").",
       "The input's comments are not kept: see doc/configuration.md for the fields."});
  std::ofstream out(o.out);
  out << written;
  if (!out) {
    throw std::runtime_error("cannot write " + o.out);
  }
  std::printf("\nwrote %s (%zu of %zu sensors fitted)\n", o.out.c_str(), c.fitted(),
              c.modules.size() + c.boards.size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    return run(o);
  } catch (const rf::ParamError& e) {
    std::cerr << "calibrate_layout: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "calibrate_layout: " << e.what() << "\n";
    return 1;
  }
}
