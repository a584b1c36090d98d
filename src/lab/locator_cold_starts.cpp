// SPDX-License-Identifier: BSD-3-Clause
// lab locator_cold_starts: issue 14's cold-start benchmark (evaluation/cold_starts.hpp).
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>

#include "lab_commands.hpp"
#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/measurement_models.hpp"
#include "radio_follow/evaluation/closed_loop.hpp"
#include "radio_follow/evaluation/cold_starts.hpp"

namespace {

radio_follow::cli::CommandLine coldStartsCommandLine() {
  namespace lab = radio_follow::lab;
  radio_follow::cli::CommandLine cli(
      "lab locator_cold_starts",
      "usage: lab locator_cold_starts [--layout L] [--trials N] [--first N]\n"
      "         [--sensor-profile ideal|realistic] [--locator-overrides FILE] [--config-dir DIR]\n"
      "         [--trace TRIAL]\n",
      "Issue 14's cold-start benchmark (evaluation/cold_starts.hpp): the locator started from\n"
      "nothing, many times, on a standing robot's simulated sensors with the shipped\n"
      "config/locator.yaml; how often, and how long, a drivable estimate sits on the mirror\n"
      "image. Lists the trials that sat on the mirror for more than 1 s. Each trial has its own\n"
      "random stream, so `--first N --trials 1 --trace N` runs trial N alone.\n");
  cli.options()("layout", lab::value("L", "spot"), "config/layouts/<L>.yaml")(
      "trials", lab::value("N", "10000"), "cold starts, >= 1")("first", lab::value("N", "0"),
                                                               "the first trial's index")(
      "sensor-profile", lab::value("P", "realistic"), "ideal or realistic")(
      "locator-overrides", lab::value("FILE"), "YAML over config/locator.yaml")(
      "config-dir", lab::value("DIR", RF_CONFIG_DIR), "the shipped configuration's folder")(
      "trace", lab::value("TRIAL"),
      "print every update of that trial (status, error, hypotheses) and, before each, the "
      "ranges and bearings it got beside what an exact sensor would have reported");
  return cli;
}

struct ColdStartsOptions {
  std::string layout;
  std::size_t trials = 10000;
  std::size_t first = 0;
  std::string profile_name;
  radio_follow::sim::SensorProfile profile = radio_follow::sim::SensorProfile::kRealistic;
  std::string locator_overrides;
  std::string config_dir;
  std::optional<std::size_t> trace;
};

ColdStartsOptions readColdStartsOptions(const radio_follow::lab::po::variables_map& values) {
  namespace lab = radio_follow::lab;
  ColdStartsOptions o;
  o.layout = values["layout"].as<std::string>();
  o.trials = static_cast<std::size_t>(lab::count(values, "trials", 1));
  o.first = static_cast<std::size_t>(lab::count(values, "first", 0));
  o.profile_name = values["sensor-profile"].as<std::string>();
  o.profile = radio_follow::sim::parseSensorProfile(o.profile_name, "--sensor-profile");
  o.locator_overrides = radio_follow::cli::CommandLine::text(values, "locator-overrides");
  o.config_dir = values["config-dir"].as<std::string>();
  if (values.count("trace")) {
    const std::string text = values["trace"].as<std::string>();
    o.trace = static_cast<std::size_t>(radio_follow::cli::wholeNumber(
        "--trace", text, static_cast<double>(o.first), static_cast<double>(o.first + o.trials - 1),
        "a trial index in [--first, --first + --trials)"));
  }
  return o;
}

}  // namespace

int radio_follow::lab::locatorColdStartsMain(int argc, char** argv) {
  namespace rf = radio_follow;
  const ColdStartsOptions o = coldStartsCommandLine().parse(argc, argv, readColdStartsOptions);
  try {
    // The lockstep loop's loader: the shipped simulator and locator files, as the robot runs.
    const rf::evaluation::ClosedLoopConfig c = rf::evaluation::loadClosedLoopConfig(
        o.config_dir, o.layout, "outdoor_loop", rf::evaluation::FollowController::kVelocity, 1, "",
        o.locator_overrides, o.profile);
    rf::evaluation::ColdStartParams params;
    params.trials = o.trials;
    params.first_trial = o.first;
    if (o.trace) {
      const std::size_t traced = *o.trace;
      std::printf(
          "trial %zu: t (s), status, estimate x y (m), error (m), hypotheses, "
          "weight, alternative x y (m)\n",
          traced);
      params.observer = [traced](std::size_t trial, double now,
                                 const rf::estimation::LocatorEstimate& e,
                                 const Eigen::Vector3d& target) {
        if (trial != traced) {
          return;
        }
        std::printf("%.2f %s %.3f %.3f %.3f %d %.3f %.3f %.3f\n", now, rf::toString(e.status),
                    e.position.x(), e.position.y(), (e.position - target).head<2>().norm(),
                    e.hypotheses, e.hypothesis_weight, e.alternative.x(), e.alternative.y());
      };
      // Before each update, the readings it got beside an exact sensor of the layout as
      // designed.
      const rf::Layout& layout = c.layout;
      params.reading_observer = [traced, &layout](std::size_t trial,
                                                  const rf::evaluation::SensorReading& reading,
                                                  const Eigen::Vector3d& person) {
        if (trial != traced) {
          return;
        }
        if (reading.kind == rf::evaluation::SensorReading::Kind::kRange) {
          const rf::TwrModule& m = layout.twr_modules[reading.sensor];
          std::printf("  %.3f range %s %.3f m raw (the person %.3f m away)\n", reading.t,
                      m.id.c_str(), reading.value, (person - m.position).norm());
          return;
        }
        const rf::AoaBoard& b = layout.aoa_boards[reading.sensor];
        const Eigen::Vector2d exact =
            rf::estimation::predictBearing(person, b.position, b.orientation.toRotationMatrix());
        std::printf(
            "  %.3f bearing %s azimuth %.1f deg, elevation %.1f deg (the person at %.1f "
            "deg in its frame)\n",
            reading.t, b.id.c_str(), rf::rad2deg(reading.value), rf::rad2deg(reading.elevation),
            rf::rad2deg(exact.x()));
      };
    }
    const rf::evaluation::ColdStartResult r =
        rf::evaluation::runColdStarts(c.layout, c.world, c.locator, params);
    std::printf(
        "layout %s, %s sensors, %zu cold starts (%d robots, person %.1f-%.1f m, %.0f s each)\n",
        o.layout.c_str(), o.profile_name.c_str(), r.trials, params.robots, params.min_distance,
        params.max_distance, params.duration);
    std::printf(
        "mirror locks longer than 1 s: %zu; trials ever on the mirror while usable: %zu; "
        "longest %.2f s\n",
        r.locks.size(), r.mirror_any, r.longest_mirror_s);
    for (const rf::evaluation::MirrorLock& lock : r.locks) {
      std::printf(
          "  trial %zu (robot %llu): person at %.2f m, %.0f deg; on the mirror %.2f s "
          "from %.2f s\n",
          lock.trial, static_cast<unsigned long long>(lock.robot), lock.target.head<2>().norm(),
          rf::rad2deg(std::atan2(lock.target.y(), lock.target.x())), lock.longest_s, lock.start_s);
    }
    std::printf(
        "usable (OK or DEGRADED) in %zu trials, median after %.2f s; AMBIGUOUS %.2f %% "
        "of updates\n",
        r.usable, r.median_time_to_usable,
        100.0 * static_cast<double>(r.ambiguous_updates) /
            static_cast<double>(std::max<std::size_t>(1, r.updates)));
    std::printf(
        "error after 1 s: median %.3f m, p95 %.3f m; NEES mean %.2f (2D: 2 is consistent), "
        "median %.2f (1.39), p99 %.1f (9.2), largest %.0f, inside the 95 %% ellipse %.3f "
        "(0.95), over %zu estimates\n",
        r.error_median, r.error_p95, r.nees_mean, r.nees_median, r.nees_p99, r.nees_max,
        r.within_95, r.nees_samples);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lab locator_cold_starts: %s\n", e.what());
    return 1;
  }
}
