// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A parameter table's entries against the commented YAML that ships them and the doc
// page's parameter table: each entry is in both, with the table's default (the defaults
// are declared once, in the table; the YAML and the doc are checked copies).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "radio_follow/common/param_table.hpp"

namespace radio_follow {

inline std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The YAML value at "a/b", or an undefined node (reset(), not operator=: assigning a
/// yaml-cpp node writes into the node it refers to).
inline YAML::Node lookup(const YAML::Node& root, const std::string& name) {
  YAML::Node node;
  node.reset(root);
  std::size_t start = 0;
  while (true) {
    const std::size_t slash = name.find('/', start);
    if (!node.IsMap()) {
      return YAML::Node(YAML::NodeType::Undefined);
    }
    const YAML::Node child =
        static_cast<const YAML::Node&>(node)[name.substr(start, slash - start)];
    node.reset(child);
    if (slash == std::string::npos || !node.IsDefined()) {
      return node;
    }
    start = slash + 1;
  }
}

inline bool sameValue(const ParamValue& expected, const std::string& written) {
  if (const double* d = std::get_if<double>(&expected)) {
    try {
      return std::abs(std::stod(written) - *d) <= 1e-9 * std::max(1.0, std::abs(*d));
    } catch (const std::exception&) {
      return false;
    }
  }
  std::string text = paramValueText(expected);
  if (std::holds_alternative<std::string>(expected)) {
    text = std::get<std::string>(expected);
  }
  if (text.empty() && (written == "(required)" || written == "required")) {
    return true;  // no default: the node refuses to start without it
  }
  std::string w = written;
  for (const char quote : {'"', '\'', '`'}) {
    w.erase(std::remove(w.begin(), w.end(), quote), w.end());
  }
  return w == text;
}

/// The default column of the doc row "| `name` |" or "| `~name` |": the column headed
/// "default" in the row's table.
inline std::string docDefault(const std::string& doc, const std::string& name, bool& found) {
  std::size_t at = doc.find("| `" + name + "` |");
  if (at == std::string::npos) {
    at = doc.find("| `~" + name + "` |");
  }
  found = at != std::string::npos;
  if (!found) {
    return "";
  }
  const auto cells = [&](std::size_t line_start) {
    const std::size_t end = doc.find('\n', line_start);
    std::vector<std::string> out;
    std::stringstream line(doc.substr(line_start, end - line_start));
    std::string cell;
    std::getline(line, cell, '|');  // before the first bar
    while (std::getline(line, cell, '|')) {
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      out.push_back(cell);
    }
    return out;
  };
  std::size_t header = at;  // the table's first line: go up while the lines are rows
  while (header > 0) {
    const std::size_t previous = doc.rfind('\n', header - 2);
    const std::size_t start = previous == std::string::npos ? 0 : previous + 1;
    if (doc.compare(start, 1, "|") != 0) {
      break;
    }
    header = start;
  }
  const std::vector<std::string> titles = cells(header);
  const std::vector<std::string> row = cells(at);
  for (std::size_t i = 0; i < titles.size() && i < row.size(); ++i) {
    std::string title = titles[i];
    std::transform(title.begin(), title.end(), title.begin(), ::tolower);
    if (title == "default") {
      return row[i];
    }
  }
  found = false;
  return "";
}

/// Every entry of `table` is in `yaml_files` (config/; the last one that has it counts;
/// none: not checked) and in the parameter table of `doc_file` (doc/; "": not checked),
/// with the table's default.
template <typename S>
void expectCovered(const ParamTable<S>& table, const std::vector<std::string>& yaml_files,
                   const std::string& doc_file, const std::vector<std::string>& not_in_yaml = {}) {
  std::vector<YAML::Node> files;
  for (const std::string& f : yaml_files) {
    files.push_back(YAML::LoadFile(std::string(RF_CONFIG_DIR) + "/" + f));
  }
  const std::string doc =
      doc_file.empty() ? "" : readFile(std::string(RF_CONFIG_DIR) + "/../doc/" + doc_file);
  ASSERT_TRUE(doc_file.empty() || !doc.empty()) << doc_file;
  S defaults;  // (S{} trips a false maybe-uninitialized warning in GCC 12 for derived aggregates)
  for (const auto& e : table.entries()) {
    const ParamValue value = e.get(defaults);
    if (!files.empty() &&
        std::find(not_in_yaml.begin(), not_in_yaml.end(), e.name) == not_in_yaml.end()) {
      YAML::Node written;
      for (const YAML::Node& f : files) {
        const YAML::Node n = lookup(f, e.name);
        if (n.IsDefined()) {
          written.reset(n);
        }
      }
      EXPECT_TRUE(written.IsDefined() && written.IsScalar())
          << e.name << ": not in " << yaml_files.back() << " (default " << paramValueText(value)
          << ")";
      if (written.IsDefined() && written.IsScalar()) {
        EXPECT_TRUE(sameValue(value, written.Scalar()))
            << e.name << ": " << yaml_files.back() << " says " << written.Scalar()
            << ", the table's default is " << paramValueText(value);
      }
    }
    if (doc_file.empty()) {
      continue;
    }
    bool found = false;
    const std::string documented = docDefault(doc, e.name, found);
    EXPECT_TRUE(found) << e.name << ": no row \"| `" << e.name << "` |\" in doc/" << doc_file;
    if (found) {
      EXPECT_TRUE(sameValue(value, documented))
          << e.name << ": doc/" << doc_file << " says " << documented << ", the table's default is "
          << paramValueText(value);
    }
  }
}

}  // namespace radio_follow
