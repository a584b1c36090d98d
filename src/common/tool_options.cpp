// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/tool_options.hpp"

#include <algorithm>
#include <cctype>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {

std::optional<std::string> readToolOptions(int argc, const char* const* argv,
                                           std::map<std::string, std::string>& options) {
  for (int i = 1; i < argc; i += 2) {
    const auto option = options.find(argv[i]);
    if (option == options.end() || i + 1 >= argc) {
      return std::string("unknown option or no value: ") + argv[i];
    }
    option->second = argv[i + 1];
  }
  return std::nullopt;
}

std::size_t toolCount(const std::string& option, const std::string& value, std::size_t min,
                      std::size_t max) {
  const std::string expected =
      "a whole number in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  const bool digits =
      !value.empty() && value.size() <= 18 &&
      std::all_of(value.begin(), value.end(), [](unsigned char c) { return std::isdigit(c); });
  require(digits, option, value, expected);
  const std::size_t count = static_cast<std::size_t>(std::stoull(value));
  require(count >= min && count <= max, option, value, expected);
  return count;
}

}  // namespace radio_follow
