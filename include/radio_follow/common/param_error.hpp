// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace radio_follow {

/// A configuration value that cannot be used. Thrown by every `validate()` and config
/// loader; nodes catch it before any subscriber exists and exit non-zero.
/// The message names the parameter, the value given and what is expected.
class ParamError : public std::runtime_error {
 public:
  ParamError(const std::string& name, const std::string& value, const std::string& expected)
      : std::runtime_error("parameter '" + name + "' = " + value + ": expected " + expected),
        name_(name),
        value_(value),
        expected_(expected) {}

  /// The offending parameter's name (dotted path for nested YAML fields).
  const std::string& name() const { return name_; }
  /// The same complaint about `name`: a table included under a prefix knows its entries
  /// by their short names only.
  ParamError renamed(const std::string& name) const { return {name, value_, expected_}; }

 private:
  std::string name_;
  std::string value_;
  std::string expected_;
};

/// Renders a value for a ParamError message.
template <typename T>
std::string paramValueString(const T& value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

inline std::string paramValueString(const std::string& value) {
  return "'" + value + "'";
}

/// Throws ParamError unless `ok`.
template <typename T>
void require(bool ok, const std::string& name, const T& value, const std::string& expected) {
  if (!ok) {
    throw ParamError(name, paramValueString(value), expected);
  }
}

}  // namespace radio_follow
