// SPDX-License-Identifier: BSD-3-Clause
// lab rssi_filter_compare: seed 002's Table 2 in shape, on simulated RSSI: the RSSI filters
// (control/rssi_filter.hpp) with the tag held still and while the robot drives at it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lab_commands.hpp"
#include "radio_follow/common/error_statistics.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/control/rssi_filter.hpp"
#include "radio_follow/control/rssi_model.hpp"
#include "radio_follow/sim/rssi_channel.hpp"

namespace rf = radio_follow;

namespace {

using Type = rf::control::RssiFilterParams::Type;

constexpr std::array<Type, 4> kTypes{Type::kNone, Type::kMean, Type::kMedian, Type::kKalman};
constexpr std::array<double, 8> kDistances{1.1, 1.4, 1.7, 2.0, 3.0, 4.0, 6.0, 8.0};
/// Readings a filter gets before its output counts (a full window, and the Kalman's start).
constexpr int kWarmUp = 50;

/// Seed 002 Table 2, average distance error (m) for Kalman, mean, median at the distances
/// it shares with kDistances (1.10, 1.40, 1.70, 2.00 m); NaN where it has no row.
double paperAverage(double distance, Type type) {
  const std::map<double, std::array<double, 3>> rows{{1.1, {0.24, 0.24, 0.43}},
                                                     {1.4, {0.26, 0.26, 0.40}},
                                                     {1.7, {0.81, 0.81, 0.83}},
                                                     {2.0, {0.84, 0.86, 0.96}}};
  const auto row = rows.find(distance);
  if (row == rows.end() || type == Type::kNone) {
    return std::nan("");
  }
  return row->second[type == Type::kKalman ? 0 : type == Type::kMean ? 1 : 2];
}

const char* name(Type type) {
  switch (type) {
    case Type::kNone:
      return "raw";
    case Type::kMean:
      return "mean";
    case Type::kMedian:
      return "median";
    case Type::kKalman:
      return "kalman";
  }
  return "?";
}

std::string cell(double v, const char* format = "%.2f") {
  if (!std::isfinite(v)) {
    return "-";
  }
  char text[32];
  std::snprintf(text, sizeof(text), format, v);
  return text;
}

double stddev(const std::vector<double>& v) {
  const double m = rf::mean(v);
  double s = 0.0;
  for (double x : v) {
    s += (x - m) * (x - m);
  }
  return std::sqrt(s / static_cast<double>(v.size()));
}

/// The log-distance model fitted to `readings` raw readings at each distance.
rf::control::RssiFit calibrate(int readings, unsigned long seed) {
  std::vector<rf::control::RssiSample> samples;
  for (std::size_t k = 0; k < kDistances.size(); ++k) {
    rf::sim::RssiChannel channel(rf::AoaBoardKind::kXplrAoa1);
    rf::sim::Rng rng(seed * 1000003UL + 500 + k);
    for (int i = 0; i < readings; ++i) {
      if (const auto r = channel.sample(kDistances[k], 0.0, i / channel.figures().rate, rng)) {
        samples.push_back({kDistances[k], *r});
      }
    }
  }
  return rf::control::fitRssiModel(samples);
}

void staticTable(const rf::control::RssiFilterParams& base, const rf::control::RssiModel& model,
                 int readings, unsigned long seed) {
  std::printf(
      "| distance (m) | filter | RSSI mean (dBm) | RSSI std (dB) | abs. error median (m) | "
      "mean (m) | p95 (m) | max (m) | seed 002 average (m) |\n"
      "|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < kDistances.size(); ++k) {
    const double d = kDistances[k];
    // One stream per distance, fed to every filter: the filters see the same readings.
    rf::sim::RssiChannel channel(rf::AoaBoardKind::kXplrAoa1);
    rf::sim::Rng rng(seed * 1000003UL + k);
    std::vector<double> stream;
    for (int i = 0; i < readings + kWarmUp; ++i) {
      stream.push_back(channel.sample(d, 0.0, i / channel.figures().rate, rng).value_or(NAN));
    }
    for (const Type type : kTypes) {
      rf::control::RssiFilterParams p = base;
      p.type = type;
      rf::control::RssiFilter filter(p);
      std::vector<double> rssi;
      std::vector<double> error;
      for (std::size_t i = 0; i < stream.size(); ++i) {
        const auto out = filter.update(stream[i]);
        if (out && i >= static_cast<std::size_t>(kWarmUp)) {
          rssi.push_back(*out);
          error.push_back(std::abs(model.distance(*out) - d));
        }
      }
      std::printf("| %.1f | %s | %.1f | %.2f | %.2f | %.2f | %.2f | %.2f | %s |\n", d, name(type),
                  rf::mean(rssi), stddev(rssi), rf::quantile(error, 0.5), rf::mean(error),
                  rf::quantile(error, 0.95), *std::max_element(error.begin(), error.end()),
                  cell(paperAverage(d, type)).c_str());
    }
  }
}

/// Readings until a noise-free 10 dB step is 90 % through the filter.
int riseReadings(const rf::control::RssiFilterParams& p) {
  rf::control::RssiFilter filter(p);
  for (int i = 0; i < 200; ++i) {
    filter.update(-60.0);
  }
  for (int i = 1; i < 1000; ++i) {
    if (*filter.update(-50.0) >= -51.0) {
      return i;
    }
  }
  return -1;
}

void approachTable(const rf::control::RssiFilterParams& base, const rf::control::RssiModel& model,
                   double speed, int runs, unsigned long seed) {
  const double start = 8.0;
  const double stop = 1.0;
  std::printf(
      "| filter | 90 %% step (readings) | distance bias (m) | abs. error median (m) | mean (m) | "
      "p95 (m) | abs. error mean, 1-3 m (m) |\n|---|---|---|---|---|---|---|\n");
  for (const Type type : kTypes) {
    rf::control::RssiFilterParams p = base;
    p.type = type;
    std::vector<double> signed_error;
    std::vector<double> error;
    std::vector<double> near_error;
    for (int run = 0; run < runs; ++run) {
      rf::control::RssiFilter filter(p);
      rf::sim::RssiChannel channel(rf::AoaBoardKind::kXplrAoa1);
      rf::sim::Rng rng(seed * 1000003UL + 1000 + static_cast<unsigned long>(run));
      const double rate = channel.figures().rate;
      for (int i = 0;; ++i) {
        const double t = i / rate;
        const double d = start - speed * t;
        if (d < stop) {
          break;
        }
        const auto out = filter.update(channel.sample(d, 0.0, t, rng).value_or(NAN));
        if (out) {
          signed_error.push_back(model.distance(*out) - d);
          error.push_back(std::abs(signed_error.back()));
          if (d <= 3.0) {
            near_error.push_back(error.back());
          }
        }
      }
    }
    std::printf("| %s | %d | %+.2f | %.2f | %.2f | %.2f | %.2f |\n", name(type), riseReadings(p),
                rf::mean(signed_error), rf::quantile(error, 0.5), rf::mean(error),
                rf::quantile(error, 0.95), rf::mean(near_error));
  }
}

rf::cli::CommandLine rssiFilterCommandLine() {
  namespace lab = rf::lab;
  rf::cli::CommandLine cli(
      "lab rssi_filter_compare",
      "usage: lab rssi_filter_compare [--seed S] [--readings N] [--window N] [--process-noise Q]\n"
      "         [--measurement-noise R] [--speed V] [--runs N]\n",
      "Seed 002's Table 2 in shape, on simulated RSSI (sim::RssiChannel: the thesis's measured\n"
      "XPLR-AOA-1 RSSI tables with time-correlated shadowing, fades and dropouts): a tag held\n"
      "at known distances, the raw readings against the moving mean, the moving median and the\n"
      "1-D Kalman estimator (control/rssi_filter.hpp), each turned into a distance by the\n"
      "log-distance model fitted to a separate calibration run (control::fitRssiModel, as\n"
      "lab rssi_calibration_fit does). Then the same filters while the robot drives at the\n"
      "tag, where a filter's lag costs as much as its noise. Deterministic; prints Markdown.\n");
  cli.options()("seed", lab::value("S", "1"), "the readings' seed")(
      "readings", lab::value("N", "3000"), "readings per distance, >= 1")(
      "window", lab::value("N", "10"), "the mean's and the median's window, readings")(
      "process-noise", lab::value("Q", "1"), "the Kalman filter's process noise, dB^2")(
      "measurement-noise", lab::value("R", "25"), "the Kalman filter's measurement noise, dB^2")(
      "speed", lab::value("V", "0.3"), "the robot's speed towards the tag, m/s")(
      "runs", lab::value("N", "200"), "approach runs, >= 1");
  return cli;
}

struct RssiFilterOptions {
  unsigned long seed = 1;
  int readings = 3000;
  int runs = 200;
  double speed = 0.3;
  rf::control::RssiFilterParams filter;
};

RssiFilterOptions readRssiFilterOptions(const rf::lab::po::variables_map& values) {
  namespace lab = rf::lab;
  RssiFilterOptions o;
  o.seed = static_cast<unsigned long>(lab::count(values, "seed", 0));
  o.readings = static_cast<int>(lab::count(values, "readings", 1));
  o.runs = static_cast<int>(lab::count(values, "runs", 1));
  o.speed = lab::number(values, "speed", "a speed > 0 m/s", [](double v) { return v > 0.0; });
  const auto any = [](double) { return true; };  // the filter's validate() checks them
  o.filter.window.window = static_cast<int>(lab::count(values, "window", 0));
  o.filter.kalman.process_noise = lab::number(values, "process-noise", "a variance in dB^2", any);
  o.filter.kalman.measurement_noise =
      lab::number(values, "measurement-noise", "a variance in dB^2", any);
  o.filter.validate();
  return o;
}

}  // namespace

int radio_follow::lab::rssiFilterCompareMain(int argc, char** argv) {
  const RssiFilterOptions o = rssiFilterCommandLine().parse(argc, argv, readRssiFilterOptions);
  const unsigned long seed = o.seed;
  const int readings = o.readings;
  const int runs = o.runs;
  const double speed = o.speed;
  const control::RssiFilterParams& filter = o.filter;
  try {
    const rf::control::RssiFit fit = calibrate(readings, seed);
    const rf::sim::RssiChannelFigures figures;
    std::printf(
        "Simulated XPLR-AOA-1 RSSI at %.0f Hz, tag on boresight: the thesis's tables' mean and "
        "spread, %.0f %% of the variance as shadowing with tau %.1f s, fades starting with "
        "probability %.2f per reading (mean %.0f readings, %.0f dB mean depth), %.0f %% "
        "dropouts. Filters: window %d readings; Kalman Q %.3g dB^2, R %.3g dB^2 (steady gain "
        "%.3f). Log-distance model fitted to a separate calibration run (%d readings per "
        "distance): rssi_at_1m %.2f dBm, exponent %.3f, rms residual %.2f dB.\n\n",
        figures.rate, 100.0 * figures.shadow_share, figures.shadow_tau, figures.fade_start,
        1.0 / (1.0 - figures.fade_continue), figures.fade_min + figures.fade_mean_excess,
        100.0 * figures.dropout, filter.window.window, filter.kalman.process_noise,
        filter.kalman.measurement_noise, filter.kalman.steadyStateGain(), readings,
        fit.model.rssi_at_1m, fit.model.exponent, fit.rms_residual_db);
    std::printf("Tag at a fixed distance, %d readings after %d of warm-up:\n\n", readings, kWarmUp);
    staticTable(filter, fit.model, readings, seed);
    std::printf("\nRobot driving at the tag from 8 m to 1 m at %.2f m/s, %d runs:\n\n", speed,
                runs);
    approachTable(filter, fit.model, speed, runs, seed);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lab rssi_filter_compare: %s\n", e.what());
    return 1;
  }
}
