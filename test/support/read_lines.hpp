// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// For rostest nodes that check what a stand-in program logged (test/ros/fake_speaker.sh).

#include <fstream>
#include <string>
#include <vector>

namespace radio_follow::test {

/// The lines of the text file at `path`; none when it does not exist (yet).
inline std::vector<std::string> readLines(const std::string& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    lines.push_back(line);
  }
  return lines;
}

}  // namespace radio_follow::test
