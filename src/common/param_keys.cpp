// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/param_keys.hpp"

#include <algorithm>
#include <cctype>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace {

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

bool isBelow(const std::string& key, const std::string& ns) {
  return key.size() > ns.size() && key.compare(0, ns.size(), ns) == 0 && key[ns.size()] == '/';
}

}  // namespace

std::string nearestKey(const std::string& key, const std::set<std::string>& known) {
  std::string best;
  std::size_t best_distance = key.size() / 3 + 1;
  for (const std::string& candidate : known) {
    const std::size_t d = editDistance(key, candidate);
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

void requireKnownKeys(const std::vector<PresentKey>& present, const std::set<std::string>& known,
                      const std::vector<std::string>& owned, const std::string& prefix) {
  for (const PresentKey& key : present) {
    if (known.count(key.name) > 0) {
      continue;
    }
    const bool is_owned = std::any_of(owned.begin(), owned.end(), [&](const std::string& ns) {
      return isBelow(key.name, ns);
    });
    if (is_owned) {
      continue;
    }
    const std::string nearest = nearestKey(key.name, known);
    throw ParamError(prefix + key.name, key.value,
                     nearest.empty()
                         ? std::string("a known key (a typo, or a file meant for another node?)")
                         : "a known key: did you mean '" + prefix + nearest + "'?");
  }
}

std::string normalizeId(const std::string& id) {
  const auto first = id.find_first_not_of(" \t");
  if (first == std::string::npos) {
    return "";
  }
  const auto last = id.find_last_not_of(" \t");
  std::string out = id.substr(first, last - first + 1);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return out;
}

}  // namespace radio_follow
