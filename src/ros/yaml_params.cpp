// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/yaml_params.hpp"

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

}  // namespace

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

YAML::Node YamlParams::lookup(const std::string& name) const {
  return child(root_, name, 0);
}

void YamlParams::requireAllKnown() const {
  std::vector<PresentKey> present;
  flatten(root_, "", present);
  requireKnownKeys(present, known_, {}, "~");
}

}  // namespace radio_follow
