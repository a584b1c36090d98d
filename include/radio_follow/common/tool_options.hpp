// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <limits>
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

/// `value`, given for `option`, as a whole number in [min, max]: digits only, so "12x",
/// "-1", "1e3" and "" are refused, not read as 12, a huge count, 1 or 0. Throws ParamError
/// naming the option, its value and what is expected.
std::size_t toolCount(const std::string& option, const std::string& value, std::size_t min = 0,
                      std::size_t max = std::numeric_limits<int>::max());

}  // namespace radio_follow
