// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <dynamic_reconfigure/config_tools.h>
#include <ros/ros.h>

#include <boost/any.hpp>
#include <stdexcept>
#include <string>

#include "radio_follow/common/param_table.hpp"

namespace radio_follow {

/// The dynamic_reconfigure field of parameter `name`: '/' becomes '_' (linear_pid/kp ->
/// linear_pid_kp), since .cfg names cannot nest.
inline std::string tuningName(const std::string& name) {
  std::string out = name;
  for (char& c : out) {
    if (c == '/') {
      c = '_';
    }
  }
  return out;
}

/// The .cfg field every server answers in, not a parameter: the last refused change and
/// why, empty after an accepted one (ReconfigureServer).
constexpr char kRefusedField[] = "refused";

/// The table entry behind the .cfg field `field`; throws std::logic_error when there is
/// none (a .cfg field no parameter backs would be tuned into nothing).
template <typename S>
const typename ParamTable<S>::Entry& entryForTuning(const ParamTable<S>& table,
                                                    const std::string& field) {
  for (const auto& e : table.entries()) {
    if (tuningName(e.name) == field) {
      return e;
    }
  }
  throw std::logic_error("reconfigure field '" + field + "' has no parameter table entry");
}

/// The live-tuning mapping, derived from the parameter table by name: every field of
/// `Config` is the table entry of the same (tuningName) name, with the same unit.
template <typename Config, typename S>
Config tuningFromTable(const ParamTable<S>& table, const S& s) {
  Config config = Config::__getDefault__();
  for (const auto& d : Config::__getParamDescriptions__()) {
    if (d->name == kRefusedField) {
      continue;
    }
    dynamic_reconfigure::Config msg;
    std::visit(
        [&](const auto& v) { dynamic_reconfigure::ConfigTools::appendParameter(msg, d->name, v); },
        entryForTuning(table, d->name).get(s));
    d->fromMessage(msg, config);
  }
  return config;
}

/// `s` with every field of `config` stored through its table entry (a choice outside its
/// set throws ParamError; the caller validates the result).
template <typename Config, typename S>
S tableFromTuning(const ParamTable<S>& table, const Config& config, S s) {
  for (const auto& d : Config::__getParamDescriptions__()) {
    if (d->name == kRefusedField) {
      continue;
    }
    const auto& e = entryForTuning(table, d->name);
    boost::any any;
    d->getValue(config, any);
    ParamValue value = e.get(s);
    std::visit([&](auto& v) { v = boost::any_cast<std::decay_t<decltype(v)>>(any); }, value);
    e.set(s, value);
  }
  return s;
}

/// Writes the tuned fields of `Config` back under their parameter names in `nh`, so that
/// `rosparam get` and a respawned node see the tuned values.
template <typename Config, typename S>
void writeTuned(const ros::NodeHandle& nh, const ParamTable<S>& table, const S& s) {
  for (const auto& d : Config::__getParamDescriptions__()) {
    if (d->name == kRefusedField) {
      continue;
    }
    const auto& e = entryForTuning(table, d->name);
    std::visit([&](const auto& v) { nh.setParam(e.name, v); }, e.get(s));
  }
}

}  // namespace radio_follow
