// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// For the tests of the command-line tools: run a tool built next to the test binary (the
// devel space's lib/radio_follow) as a user would, and read the files it writes.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace radio_follow::test {

inline std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs `tool` with `args` (shell words); returns its exit code and puts its output
/// (stdout + stderr) in `output`.
inline int runTool(const std::string& tool, const std::string& args, std::string& output) {
  const std::filesystem::path dir = std::filesystem::read_symlink("/proc/self/exe").parent_path();
  const std::string log = std::filesystem::temp_directory_path() / (tool + "_test.log");
  const int status =
      std::system(((dir / tool).string() + " " + args + " > " + log + " 2>&1").c_str());
  output = readFile(log);
  return WEXITSTATUS(status);
}

}  // namespace radio_follow::test
