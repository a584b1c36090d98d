// SPDX-License-Identifier: BSD-3-Clause
// Fits the log-distance RSSI model rssi = rssi_at_1m - 10 n log10(d) to a CSV table of
// "distance,rssi" rows (metres, dBm; a header line and '#' comments are skipped) and
// prints the parameters plus the YAML snippet for homing_controller.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "radio_follow/control/rssi_model.hpp"

namespace {

bool parseRow(const std::string& line, radio_follow::control::RssiSample& sample) {
  std::istringstream in(line);
  char comma = 0;
  return static_cast<bool>(in >> sample.distance >> comma >> sample.rssi) && comma == ',';
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help") {
    std::cerr << "usage: rssi_calibration_fit <samples.csv>\n"
                 "  CSV rows: distance_m,rssi_dbm (header and # comments skipped)\n";
    return 2;
  }
  std::ifstream file(argv[1]);
  if (!file) {
    std::cerr << "cannot open " << argv[1] << "\n";
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
      std::cerr << argv[1] << ":" << line_number << ": expected 'distance,rssi'\n";
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
