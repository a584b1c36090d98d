// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/tool_options.hpp"

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

}  // namespace radio_follow
