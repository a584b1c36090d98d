// SPDX-License-Identifier: BSD-3-Clause
// lab rssi_calibration_fit: the log-distance RSSI model fitted to a CSV of distance,rssi.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lab_commands.hpp"
#include "radio_follow/control/rssi_model.hpp"

namespace {

bool parseRow(const std::string& line, radio_follow::control::RssiSample& sample) {
  std::istringstream in(line);
  char comma = 0;
  return static_cast<bool>(in >> sample.distance >> comma >> sample.rssi) && comma == ',';
}

radio_follow::cli::CommandLine rssiFitCommandLine() {
  radio_follow::cli::CommandLine cli(
      "lab rssi_calibration_fit", "usage: lab rssi_calibration_fit SAMPLES.csv\n",
      "Fits the log-distance RSSI model rssi = rssi_at_1m - 10 n log10(d) to a CSV table of\n"
      "\"distance,rssi\" rows (metres, dBm; a header line and '#' comments are skipped) and\n"
      "prints the parameters plus the YAML snippet for homing_controller.\n");
  cli.positional("samples", 1);
  return cli;
}

std::string readRssiFitOptions(const radio_follow::lab::po::variables_map& values) {
  const auto paths = radio_follow::cli::CommandLine::texts(values, "samples");
  if (paths.empty()) {
    throw radio_follow::cli::UsageError("no SAMPLES.csv");
  }
  return paths.front();
}

}  // namespace

int radio_follow::lab::rssiCalibrationFitMain(int argc, char** argv) {
  const std::string path = rssiFitCommandLine().parse(argc, argv, readRssiFitOptions);
  std::ifstream file(path);
  if (!file) {
    std::cerr << "cannot open " << path << "\n";
    return 1;
  }
  std::vector<radio_follow::control::RssiSample> samples;
  std::string line;
  int line_number = 0;
  while (std::getline(file, line)) {
    ++line_number;
    if (line.empty() || line[0] == '#') {
      continue;
    }
    radio_follow::control::RssiSample sample;
    if (!parseRow(line, sample)) {
      if (samples.empty() && line_number == 1) {
        continue;  // header
      }
      std::cerr << path << ":" << line_number << ": expected 'distance,rssi'\n";
      return 1;
    }
    samples.push_back(sample);
  }
  try {
    const auto fit = radio_follow::control::fitRssiModel(samples);
    std::printf(
        "samples: %zu\nrssi_at_1m: %.2f dBm\npath-loss exponent n: %.3f\n"
        "rms residual: %.2f dB\n\n# homing_controller parameters\n"
        "rssi_at_1m: %.2f\nrssi_exponent: %.3f\n",
        fit.samples, fit.model.rssi_at_1m, fit.model.exponent, fit.rms_residual_db,
        fit.model.rssi_at_1m, fit.model.exponent);
  } catch (const std::invalid_argument& e) {
    std::cerr << "fit failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
