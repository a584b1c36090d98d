// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_source.hpp"

namespace radio_follow {

/// A parameter's value as loading, reconfigure and the docs see it (in its own unit).
using ParamValue = std::variant<bool, int, double, std::string>;

/// The value as the docs and the YAML files write it: 1.3, true, 'odom'.
std::string paramValueText(const ParamValue& value);

/// Bounds of a numeric parameter, in the parameter's own unit.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = true;
  bool hi_open = true;

  static Range any() { return {}; }
  static Range atLeast(double lo) { return {lo, Range{}.hi, false, true}; }
  static Range above(double lo) { return {lo, Range{}.hi, true, true}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  /// (lo, hi]
  static Range aboveUpTo(double lo, double hi) { return {lo, hi, true, false}; }
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }

  bool contains(double v) const {
    return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  /// "[0.3, 10]", "> 0", ">= 1", "any finite value".
  std::string text() const;
};

/// The one declaration of a parameter struct's parameters: name, member, unit, bounds
/// and a line of documentation per entry (STYLE.md, "a parameter is declared once").
/// Loading from ROS or YAML (load), the bounds check (check, called by the struct's
/// validate()), the live-tuning mapping (ros/common/reconfigure_table.hpp) and the
/// coverage test of config/*.yaml and doc/nodes/*.md (param_tables_test) all read it.
/// Cross-field rules stay in the struct's validate().
template <typename S>
class ParamTable {
 public:
  struct Entry {
    std::string name;  ///< parameter name below the node's namespace, "a/b" nested
    std::string unit;  ///< "m", "s", "deg", "" for none
    std::string doc;
    Range range;                       ///< numbers only
    std::vector<std::string> choices;  ///< strings with a fixed set of values
    std::function<ParamValue(const S&)> get;
    /// Stores a value of the entry's type (a choice throws ParamError when unknown).
    std::function<void(S&, const ParamValue&)> set;
  };

  /// A bool, int, double, std::string or std::size_t member.
  template <typename T>
  ParamTable& add(const std::string& name, T S::*member, const std::string& unit,
                  const std::string& doc, Range range = Range::any()) {
    Entry e{name, unit, doc, range, {}, nullptr, nullptr};
    if constexpr (std::is_same_v<T, std::size_t>) {
      e.get = [member](const S& s) { return ParamValue(static_cast<int>(s.*member)); };
      e.set = [member, name](S& s, const ParamValue& v) {
        const int count = std::get<int>(v);
        if (count < 0) {
          throw ParamError("~" + name, paramValueString(count), "an integer >= 0");
        }
        s.*member = static_cast<std::size_t>(count);
      };
    } else {
      e.get = [member](const S& s) { return ParamValue(s.*member); };
      e.set = [member](S& s, const ParamValue& v) { s.*member = std::get<T>(v); };
    }
    entries_.push_back(std::move(e));
    return *this;
  }

  /// A bool, int, double or std::string member of the member `outer` (a struct that has
  /// no table of its own, such as the simulator's noise settings).
  template <typename Sub, typename T>
  ParamTable& add(const std::string& name, Sub S::*outer, T Sub::*inner, const std::string& unit,
                  const std::string& doc, Range range = Range::any()) {
    static_assert(!std::is_same_v<T, std::size_t>, "a nested count needs a table of its own");
    entries_.push_back(
        Entry{name,
              unit,
              doc,
              range,
              {},
              [outer, inner](const S& s) { return ParamValue((s.*outer).*inner); },
              [outer, inner](S& s, const ParamValue& v) { (s.*outer).*inner = std::get<T>(v); }});
    return *this;
  }

  /// A double member stored as `scale` times the parameter (degrees in the parameter,
  /// radians in the struct: scale = pi / 180). `range` is in the parameter's unit.
  ParamTable& addScaled(const std::string& name, double S::*member, double scale,
                        const std::string& unit, const std::string& doc, Range range) {
    entries_.push_back(Entry{
        name,
        unit,
        doc,
        range,
        {},
        [member, scale](const S& s) { return ParamValue(s.*member / scale); },
        [member, scale](S& s, const ParamValue& v) { s.*member = std::get<double>(v) * scale; }});
    return *this;
  }

  /// A member of type E (an enum, or a bool) named by strings in the parameter.
  template <typename E>
  ParamTable& addChoice(const std::string& name, E S::*member,
                        std::vector<std::pair<std::string, E>> choices, const std::string& doc) {
    Entry e{name, "", doc, Range::any(), {}, nullptr, nullptr};
    for (const auto& c : choices) {
      e.choices.push_back(c.first);
    }
    e.get = [member, choices](const S& s) {
      for (const auto& c : choices) {
        if (c.second == s.*member) {
          return ParamValue(c.first);
        }
      }
      if constexpr (std::is_same_v<E, std::string>) {
        return ParamValue(s.*member);  // not one of the choices: check() names it
      } else {
        return ParamValue(std::string("?"));
      }
    };
    e.set = [member, choices, name](S& s, const ParamValue& v) {
      const std::string& text = std::get<std::string>(v);
      for (const auto& c : choices) {
        if (c.first == text) {
          s.*member = c.second;
          return;
        }
      }
      std::string expected;
      for (const auto& c : choices) {
        expected += (expected.empty() ? "" : " or ") + c.first;
      }
      throw ParamError("~" + name, paramValueString(text), expected);
    };
    entries_.push_back(std::move(e));
    return *this;
  }

  /// Every entry of `sub`, for the member `member` of type Sub, names prefixed by `prefix`.
  template <typename Sub>
  ParamTable& include(const ParamTable<Sub>& sub, Sub S::*member, const std::string& prefix = "") {
    for (const auto& e : sub.entries()) {
      entries_.push_back(Entry{prefix + e.name, e.unit, e.doc, e.range, e.choices,
                               [member, get = e.get](const S& s) { return get(s.*member); },
                               [member, set = e.set, inner = "~" + e.name,
                                outer = "~" + prefix + e.name](S& s, const ParamValue& v) {
                                 try {
                                   set(s.*member, v);
                                 } catch (const ParamError& error) {
                                   // An unknown choice names the entry as `sub` knows it: give its
                                   // full name.
                                   if (error.name() != inner) {
                                     throw;
                                   }
                                   throw error.renamed(outer);
                                 }
                               }});
    }
    return *this;
  }

  /// Every entry of a base class's table (a driver's parameters deriving from the ones
  /// every serial-line driver has).
  template <typename Base>
  ParamTable& includeBase(const ParamTable<Base>& base) {
    static_assert(std::is_base_of_v<Base, S>, "includeBase needs a base class of S");
    for (const auto& e : base.entries()) {
      entries_.push_back(
          Entry{e.name, e.unit, e.doc, e.range, e.choices,
                [get = e.get](const S& s) { return get(static_cast<const Base&>(s)); },
                [set = e.set](S& s, const ParamValue& v) { set(static_cast<Base&>(s), v); }});
    }
    return *this;
  }

  /// Reads every entry from `source`; absent keys keep the member's value. Types are
  /// checked by the source (ParamError), bounds and choices here.
  void load(const ParamSource& source, S& s) const {
    for (const Entry& e : entries_) {
      loadEntry(source, s, e);
    }
  }
  /// Reads the one entry `name` (for parameters that decide how others are read).
  void load(const ParamSource& source, S& s, const std::string& name) const {
    for (const Entry& e : entries_) {
      if (e.name == name) {
        loadEntry(source, s, e);
      }
    }
  }

  /// Throws ParamError for the first entry whose value is outside its bounds.
  void check(const S& s) const {
    for (const Entry& e : entries_) {
      const ParamValue v = e.get(s);
      const double* number = std::get_if<double>(&v);
      const int* count = std::get_if<int>(&v);
      if (number || count) {
        const double x = number ? *number : static_cast<double>(*count);
        require(e.range.contains(x), "~" + e.name, x,
                "a value " + e.range.text() + (e.unit.empty() ? "" : " " + e.unit));
      }
      const std::string* text = std::get_if<std::string>(&v);
      if (text && !e.choices.empty()) {
        std::string expected;
        for (const std::string& c : e.choices) {
          expected += (expected.empty() ? "" : " or ") + c;
        }
        require(std::find(e.choices.begin(), e.choices.end(), *text) != e.choices.end(),
                "~" + e.name, *text, expected);
      }
    }
  }

  const std::vector<Entry>& entries() const { return entries_; }
  const Entry* find(const std::string& name) const {
    for (const Entry& e : entries_) {
      if (e.name == name) {
        return &e;
      }
    }
    return nullptr;
  }

 private:
  static void loadEntry(const ParamSource& source, S& s, const Entry& e) {
    ParamValue value = e.get(s);
    std::visit(
        [&](auto& current) {
          using T = std::decay_t<decltype(current)>;
          T read = current;
          source.param(e.name, read, current);
          value = read;
        },
        value);
    e.set(s, value);
  }

  std::vector<Entry> entries_;
};

}  // namespace radio_follow
