// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace radio_follow {

/// A key found in a parameter source and the value it holds, rendered for a message.
struct PresentKey {
  std::string name;
  std::string value;
};

/// The strictness rule shared by every parameter source (ROS private namespace, node
/// YAML file, layout and scenario files): a key nobody reads is a typo until proven
/// otherwise. Throws ParamError for the first of `present` that is neither in `known` nor
/// below one of `owned` (namespaces another component writes, e.g. dynamic_reconfigure's
/// `law`), naming the key, its value and the nearest known key. `prefix` is prepended to
/// names in the message ("~" for a node's private namespace, "twr_modules[0]." ...).
void requireKnownKeys(const std::vector<PresentKey>& present, const std::set<std::string>& known,
                      const std::vector<std::string>& owned, const std::string& prefix);

/// The entry of `known` nearest to `key` by edit distance, or "" when none is close
/// enough to be a plausible typo (more than a third of the key's letters differ).
std::string nearestKey(const std::string& key, const std::set<std::string>& known);

/// An ID as every component compares it: surrounding blanks removed, upper case (the
/// DWM1001 prints its 16-bit IDs as upper-case hex; a layout may say "da12").
std::string normalizeId(const std::string& id);

}  // namespace radio_follow
