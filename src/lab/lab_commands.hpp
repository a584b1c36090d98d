// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The lab program's commands (src/lab/<name>.cpp, dispatched by src/lab/lab.cpp), and what
// their command lines share: common/command_line.hpp's parser with each option's default
// in the option table.

#include <limits>
#include <string>

#include "radio_follow/common/command_line.hpp"

namespace radio_follow {
namespace lab {

/// One command a file: `lab <name> ARGS...` calls it with argv[0] = "<name>".
int closedLoopMain(int argc, char** argv);
int experimentsMain(int argc, char** argv);
int homingExperimentMain(int argc, char** argv);
int layoutCalibrationMain(int argc, char** argv);
int locatorColdStartsMain(int argc, char** argv);
int locatorMontecarloMain(int argc, char** argv);
int locatorPcrbMain(int argc, char** argv);
int rssiCalibrationFitMain(int argc, char** argv);
int rssiFilterCompareMain(int argc, char** argv);
int standingExperimentsMain(int argc, char** argv);
int trilaterationCompareMain(int argc, char** argv);

namespace po = cli::po;

/// An option's value, named `name` in the help; `fallback` when not given (the help shows
/// it).
inline po::typed_value<std::string>* value(const char* name, const std::string& fallback) {
  return po::value<std::string>()->value_name(name)->default_value(fallback);
}

/// An option's value without a default (not given: absent from the variables_map).
inline po::typed_value<std::string>* value(const char* name) {
  return po::value<std::string>()->value_name(name);
}

/// Option `name` (declared with a default) as a whole number in [min, max]; UsageError
/// "--NAME 'TEXT': expected a whole number in [MIN, MAX]" otherwise.
inline long count(const po::variables_map& values, const std::string& name, long min,
                  long max = std::numeric_limits<int>::max()) {
  return cli::wholeNumber(
      "--" + name, values[name].as<std::string>(), static_cast<double>(min),
      static_cast<double>(max),
      "a whole number in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
}

/// Option `name` (declared with a default) as a finite number for which `ok` holds;
/// UsageError "--NAME 'TEXT': expected EXPECTED" otherwise.
template <typename Predicate>
double number(const po::variables_map& values, const std::string& name, const std::string& expected,
              Predicate ok) {
  return cli::number("--" + name, values[name].as<std::string>(), expected, ok);
}

}  // namespace lab
}  // namespace radio_follow
