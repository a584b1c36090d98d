// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The operator tools' command lines (calibrate_layout, locator_offline,
// placement_advisor) on boost::program_options: the syntax (`--opt value`, `--opt=value`,
// repeats, positional arguments), the help from the option table, and one way to refuse
// a bad line. Header-only: a tool that includes it links Boost::program_options (the
// nodes do not).

#include <boost/program_options.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace cli {

namespace po = boost::program_options;

/// A bad command line: the tool prints "<tool>: <what>" and its usage, and exits 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// `text`, given for `option`, as a finite number; UsageError "OPTION 'TEXT': expected
/// EXPECTED" for "", "12x", "nan" or "inf".
inline double number(const std::string& option, const std::string& text,
                     const std::string& expected) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value)) {
    throw UsageError(option + " '" + text + "': expected " + expected);
  }
  return value;
}

/// `text` as a number for which `ok` holds; UsageError naming both otherwise.
template <typename Predicate>
double number(const std::string& option, const std::string& text, const std::string& expected,
              Predicate ok) {
  const double value = number(option, text, expected);
  if (!ok(value)) {
    throw UsageError(option + " '" + text + "': expected " + expected);
  }
  return value;
}

/// `text` as a whole number in [min, max]; UsageError naming both otherwise.
inline long wholeNumber(const std::string& option, const std::string& text, double min, double max,
                        const std::string& expected) {
  return static_cast<long>(number(option, text, expected, [&](double v) {
    return v == std::floor(v) && v >= min && v <= max;
  }));
}

/// `text` if it is one of `allowed`; UsageError listing them otherwise.
inline std::string choice(const std::string& option, const std::string& text,
                          const std::vector<std::string>& allowed) {
  std::string list;
  for (const std::string& a : allowed) {
    if (a == text) {
      return text;
    }
    list += (list.empty() ? "" : ", ") + a;
  }
  throw UsageError(option + " '" + text + "': expected one of " + list);
}

/// A tool's command line. Declare the options (values as strings, read and checked by
/// the tool with the functions above, so that a bad value is named with what is
/// expected) and the positional arguments, then parse().
class CommandLine {
 public:
  /// `usage`: the synopsis lines; `about`: what the tool does (printed by --help before
  /// the option table).
  CommandLine(std::string tool, std::string usage, std::string about)
      : tool_(std::move(tool)),
        usage_(std::move(usage)),
        about_(std::move(about)),
        visible_("options", 92, 46) {
    visible_.add_options()("help,h", "print this help");
  }

  /// The option table (help text included): `options()("name", po::value<...>(), "help")`.
  po::options_description_easy_init options() { return visible_.add_options(); }

  /// A positional argument, `count` times (-1: any number), described in `usage`.
  void positional(const char* name, int count) {
    hidden_.add_options()(name, po::value<std::vector<std::string>>());
    positional_.add(name, count);
  }

  /// Parses argv. -h/--help prints the usage, what the tool does and the option table,
  /// and exits 0; a line program_options refuses (an unknown option, a missing value, an
  /// option given twice, too many arguments) exits 2 through fail().
  po::variables_map parse(int argc, char** argv) const {
    po::options_description all;
    all.add(visible_).add(hidden_);
    po::variables_map values;
    try {
      // Long options only as written: no abbreviations (--max would be --max-gap).
      const int style = po::command_line_style::unix_style ^ po::command_line_style::allow_guessing;
      po::store(po::command_line_parser(argc, argv)
                    .options(all)
                    .positional(positional_)
                    .style(style)
                    .run(),
                values);
      po::notify(values);
    } catch (const po::error& e) {
      fail(e.what());
    }
    if (values.count("help")) {
      std::cout << usage_ << "\n" << about_ << "\n" << visible_;
      std::exit(0);
    }
    return values;
  }

  /// parse(), then `read(values)`, which turns them into the tool's options: a UsageError
  /// or ParamError it throws (a value that is not what its option expects, a missing
  /// argument) exits 2 through fail() too.
  template <typename Read>
  auto parse(int argc, char** argv, Read read) const {
    const po::variables_map values = parse(argc, argv);
    try {
      return read(values);
    } catch (const UsageError& e) {
      fail(e.what());
    } catch (const ParamError& e) {
      fail(e.what());
    }
  }

  /// Prints "<tool>: <problem>" and the usage on stderr; exits 2.
  [[noreturn]] void fail(const std::string& problem) const {
    std::cerr << tool_ << ": " << problem << "\n" << usage_;
    std::exit(2);
  }

  /// The string value of `name`, or `fallback` when it was not given.
  static std::string text(const po::variables_map& values, const char* name,
                          const std::string& fallback = "") {
    return values.count(name) ? values[name].as<std::string>() : fallback;
  }

  /// Every value of a repeatable option or positional argument `name` (none: empty).
  static std::vector<std::string> texts(const po::variables_map& values, const char* name) {
    return values.count(name) ? values[name].as<std::vector<std::string>>()
                              : std::vector<std::string>{};
  }

 private:
  std::string tool_;
  std::string usage_;
  std::string about_;
  po::options_description visible_;
  po::options_description hidden_;
  po::positional_options_description positional_;
};

}  // namespace cli
}  // namespace radio_follow
