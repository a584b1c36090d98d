// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/yaml_params.hpp"

#include <cmath>
#include <type_traits>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"

namespace radio_follow {
namespace {

void flatten(const YAML::Node& node, const std::string& prefix, std::vector<PresentKey>& out) {
  for (const auto& kv : node) {
    const std::string name = prefix + kv.first.as<std::string>();
    if (kv.second.IsMap()) {
      flatten(kv.second, name + "/", out);
    } else {
      YAML::Emitter text;
      text << YAML::Flow << kv.second;
      out.push_back({name, text.c_str()});
    }
  }
}

/// The node at the "/"-separated path name[start..] below `node` (const access: yaml-cpp's
/// non-const operator[] would insert the keys it looks up).
YAML::Node child(const YAML::Node& node, const std::string& name, std::size_t start) {
  if (!node.IsMap()) {
    return YAML::Node(YAML::NodeType::Undefined);
  }
  const std::size_t slash = name.find('/', start);
  const YAML::Node next = node[name.substr(start, slash - start)];
  if (!next.IsDefined() || slash == std::string::npos) {
    return next;
  }
  return child(next, name, slash + 1);
}

/// `over`'s keys into `base` (recursively for mappings), as a second `rosparam load`.
void mergeInto(YAML::Node base, const YAML::Node& over) {
  for (const auto& kv : over) {
    const std::string key = kv.first.as<std::string>();
    if (kv.second.IsMap() && base[key].IsMap()) {
      mergeInto(base[key], kv.second);
    } else {
      base[key] = YAML::Clone(kv.second);
    }
  }
}

}  // namespace

YamlParams YamlParams::fromFiles(const std::vector<std::string>& paths) {
  YAML::Node merged(YAML::NodeType::Map);
  for (const std::string& path : paths) {
    mergeInto(merged, fromFile(path).root());
  }
  return YamlParams(merged);
}

YamlParams YamlParams::mergedWith(const YAML::Node& over) const {
  if (!over.IsDefined() || over.IsNull()) {
    return *this;
  }
  if (!over.IsMap()) {
    throw ParamError("parameter overrides", YAML::Dump(over), "a YAML mapping of parameters");
  }
  YAML::Node merged = YAML::Clone(root_);
  mergeInto(merged, over);
  return YamlParams(merged);
}

YamlParams YamlParams::fromFile(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ParamError("parameter file", "'" + path + "'",
                     std::string("a readable YAML file (") + e.what() + ")");
  }
  if (!root.IsMap() && !root.IsNull()) {
    throw ParamError("parameter file", "'" + path + "'", "a YAML mapping of parameters");
  }
  return YamlParams(root.IsNull() ? YAML::Node(YAML::NodeType::Map) : root);
}

template <typename T>
bool YamlParams::readAs(const std::string& name, T& out) const {
  known_.insert(name);
  const YAML::Node value = lookup(name);
  if (!value.IsDefined() || value.IsNull()) {
    return false;
  }
  try {
    out = value.as<T>();
  } catch (const YAML::Exception&) {
    throw ParamError("~" + name, YAML::Dump(value), "a value of the parameter's type");
  }
  if constexpr (std::is_floating_point_v<T>) {
    require(std::isfinite(out), "~" + name, out, "a finite number");
  }
  if constexpr (std::is_same_v<T, std::vector<double>>) {
    for (const double v : out) {
      require(std::isfinite(v), "~" + name, v, "a list of finite numbers");
    }
  }
  return true;
}

// The six types TypedParamSource reads (its overrides are inline in every user).
template bool YamlParams::readAs(const std::string&, bool&) const;
template bool YamlParams::readAs(const std::string&, int&) const;
template bool YamlParams::readAs(const std::string&, double&) const;
template bool YamlParams::readAs(const std::string&, std::string&) const;
template bool YamlParams::readAs(const std::string&, std::vector<std::string>&) const;
template bool YamlParams::readAs(const std::string&, std::vector<double>&) const;

YAML::Node YamlParams::lookup(const std::string& name) const {
  return child(root_, name, 0);
}

void YamlParams::requireAllKnown() const {
  std::vector<PresentKey> present;
  flatten(root_, "", present);
  requireKnownKeys(present, known_, {}, "~");
}

}  // namespace radio_follow
