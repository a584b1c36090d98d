// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// A shipped layout by file name, for the unit tests.

#include <string>

#include "radio_follow/config/layout.hpp"

namespace radio_follow::test {

/// config/layouts/<name>, e.g. "tracked.yaml".
inline Layout shippedLayout(const std::string& name) {
  return loadLayoutFile(std::string(RF_CONFIG_DIR) + "/layouts/" + name);
}

}  // namespace radio_follow::test
