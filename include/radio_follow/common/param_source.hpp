// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

namespace radio_follow {

/// Where a component's parameters come from: a node's private namespace on the ROS
/// parameter server (ParamReader) or a YAML file (YamlParams, for tools and the lockstep
/// closed loop without a master). Parameter structs load through this interface, so one
/// loading function serves both and the same keys mean the same thing everywhere.
///
/// Every read is strict (doc/configuration.md, "Strict parameters"): a value of the wrong
/// type or a non-finite number throws ParamError naming the parameter, an int is accepted
/// where a double is expected, and every name read is remembered so that
/// requireAllKnown() refuses the keys nobody read (a typo).
class ParamSource {
 public:
  virtual ~ParamSource() = default;

  /// `out` = the value of `name` ("a/b" is `b` inside the mapping `a`), or `fallback` when
  /// it is not set. Supported: bool, int, double, std::string, std::vector<std::string>,
  /// std::vector<double>.
  template <typename T>
  void param(const std::string& name, T& out, const T& fallback) const {
    T value;
    out = read(name, value) ? value : fallback;
  }

  /// Marks `name` as known without reading it (a key another component reads).
  virtual void allow(const std::string& name) const = 0;
  /// Throws ParamError for the first parameter present that no read asked for.
  virtual void requireAllKnown() const = 0;

 protected:
  ParamSource() = default;
  ParamSource(const ParamSource&) = default;
  ParamSource& operator=(const ParamSource&) = default;

  /// True and `out` set when `name` is present; throws ParamError when it has the wrong
  /// type. Either way `name` counts as known.
  virtual bool read(const std::string& name, bool& out) const = 0;
  virtual bool read(const std::string& name, int& out) const = 0;
  virtual bool read(const std::string& name, double& out) const = 0;
  virtual bool read(const std::string& name, std::string& out) const = 0;
  virtual bool read(const std::string& name, std::vector<std::string>& out) const = 0;
  virtual bool read(const std::string& name, std::vector<double>& out) const = 0;
};

/// The six typed reads of a ParamSource forwarded to one `readAs<T>(name, out)` template
/// of `Derived` (CRTP): a source implements one function, not six.
template <typename Derived>
class TypedParamSource : public ParamSource {
 protected:
  bool read(const std::string& name, bool& out) const override { return self().readAs(name, out); }
  bool read(const std::string& name, int& out) const override { return self().readAs(name, out); }
  bool read(const std::string& name, double& out) const override {
    return self().readAs(name, out);
  }
  bool read(const std::string& name, std::string& out) const override {
    return self().readAs(name, out);
  }
  bool read(const std::string& name, std::vector<std::string>& out) const override {
    return self().readAs(name, out);
  }
  bool read(const std::string& name, std::vector<double>& out) const override {
    return self().readAs(name, out);
  }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace radio_follow
