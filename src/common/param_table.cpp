// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/param_table.hpp"

namespace radio_follow {
namespace {

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace

std::string paramValueText(const ParamValue& value) {
  if (const bool* b = std::get_if<bool>(&value)) {
    return *b ? "true" : "false";
  }
  if (const int* i = std::get_if<int>(&value)) {
    return std::to_string(*i);
  }
  if (const double* d = std::get_if<double>(&value)) {
    return number(*d);
  }
  return "'" + std::get<std::string>(value) + "'";
}

std::string Range::text() const {
  const bool has_lo = std::isfinite(lo);
  const bool has_hi = std::isfinite(hi);
  if (has_lo && has_hi) {
    return std::string("in ") + (lo_open ? "(" : "[") + number(lo) + ", " + number(hi) +
           (hi_open ? ")" : "]");
  }
  if (has_lo) {
    return (lo_open ? "> " : ">= ") + number(lo);
  }
  if (has_hi) {
    return (hi_open ? "< " : "<= ") + number(hi);
  }
  return "that is finite";
}

}  // namespace radio_follow
