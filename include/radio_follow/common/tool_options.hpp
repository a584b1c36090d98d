// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <optional>
#include <string>

namespace radio_follow {

/// Reads a command-line tool's `--option value` pairs into `options`, whose keys are the
/// options the tool knows and whose values are their defaults. Returns the problem
/// ("unknown option or no value: ARG") at the first argument that is not a known option
/// followed by a value; nullopt when every argument was read.
std::optional<std::string> readToolOptions(int argc, const char* const* argv,
                                           std::map<std::string, std::string>& options);

}  // namespace radio_follow
