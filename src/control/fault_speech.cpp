// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/fault_speech.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <utility>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace control {
namespace {

bool startsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The task part of "<node>: <task>" (diagnostic_updater prefixes the node name).
std::string taskOf(const std::string& name) {
  const auto colon = name.find(": ");
  return colon == std::string::npos ? name : name.substr(colon + 2);
}

/// "(module 5722)" in "/dev/dwm1001_5722 (module 5722)" -> "5722".
std::string parenthesised(const std::string& hardware_id, const std::string& word) {
  const std::string open = "(" + word + " ";
  const auto start = hardware_id.find(open);
  if (start == std::string::npos) {
    return std::string();
  }
  const auto end = hardware_id.find(')', start);
  return end == std::string::npos
             ? std::string()
             : hardware_id.substr(start + open.size(), end - start - open.size());
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/// A device path, frame or topic as words: "/dev/aoa_front" -> "aoa front", without the
/// words that only repeat the kind ("aoa", "uwb", "dwm1001") when something remains.
std::string spokenLabel(const std::string& label) {
  std::vector<std::string> words;
  std::string word;
  std::string text = label;
  if (startsWith(text, "/dev/")) {
    text = text.substr(5);
  }
  for (const char c : text + " ") {
    if (c == '/' || c == '_' || c == '-' || c == ' ') {
      if (!word.empty()) {
        words.push_back(word);
      }
      word.clear();
    } else {
      word += c;
    }
  }
  std::vector<std::string> kept;
  for (const auto& w : words) {
    const std::string l = lower(w);
    if (l != "aoa" && l != "uwb" && l != "dwm1001" && l != "tty") {
      kept.push_back(w);
    }
  }
  if (kept.empty()) {
    kept = words;
  }
  std::string out;
  for (const auto& w : kept) {
    out += (out.empty() ? "" : " ") + w;
  }
  return out;
}

std::vector<std::string> split(const std::string& text, const std::string& separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) {
      return parts;
    }
    start = end + separator.size();
  }
}

}  // namespace

void FaultSpeechParams::validate(const std::string& prefix) const {
  require(std::isfinite(hold_time) && hold_time >= 0.0, prefix + "hold_time", hold_time,
          "seconds >= 0");
  require(std::isfinite(silence_timeout) && silence_timeout > 0.0, prefix + "silence_timeout",
          silence_timeout, "seconds > 0");
}

FaultSpeech::FaultSpeech(const FaultSpeechParams& params) : params_(params) {
  params_.validate();
}

std::string FaultSpeech::speakerName(const ReportedStatus& status) {
  const std::string task = taskOf(status.name);
  if (contains(task, " output ")) {
    return std::string();  // a topic-rate entry: the source's own entry says what matters
  }
  if (startsWith(task, "dwm1001 ")) {
    const std::string module = parenthesised(status.hardware_id, "module");
    return "UWB module " + spokenLabel(module.empty() ? task.substr(8) : module);
  }
  if (startsWith(task, "ublox aoa ")) {
    const std::string board = parenthesised(status.hardware_id, "board");
    return "AoA board " + spokenLabel(board.empty() ? task.substr(10) : board);
  }
  if (task == "TDoA anchors") {
    return "TDoA anchors";
  }
  if (task == "locator") {
    return "Locator";
  }
  return std::string();
}

std::map<std::string, FaultSpeech::Condition> FaultSpeech::driverConditions(
    const Source& source, const ReportedStatus& status) {
  std::map<std::string, Condition> seen;
  const std::string& name = source.name;
  if (status.level == StatusLevel::kError || status.level == StatusLevel::kStale) {
    seen["lost"] = Condition{name + " lost.", name + " back."};
  } else if (status.level == StatusLevel::kWarn) {
    if (contains(status.message, "no data") || contains(status.message, "no measurements")) {
      seen["silent"] = Condition{"No data from " + name + ".", name + " sends data again.", 1};
    } else {
      seen["warn " + status.message] = Condition{name + ": " + status.message + ".", "", 2};
    }
  }
  return seen;
}

std::map<std::string, FaultSpeech::Condition> FaultSpeech::locatorConditions(
    const ReportedStatus& status) {
  // The locator's summary: its target state, then (merged by diagnostic_updater with
  // "; ") the silent inputs (src/ros/locator/locator_node.cpp, LocatorNode::diagnose).
  std::map<std::string, Condition> seen;
  const std::string found = "Target found.";
  for (const std::string& part : split(status.message, "; ")) {
    if (part == "tracking" || part == "UNSET" || part.empty()) {
      continue;
    }
    if (part == "target lost" || part == "LOST") {
      seen["target"] = Condition{"Locator lost the target.", found};
    } else if (part == "DEGRADED") {
      seen["target"] = Condition{"Target position uncertain.", found};
    } else if (part == "AMBIGUOUS") {
      seen["target"] = Condition{"Target may be at its mirror image.", found};
    } else if (part == "HEADING_ONLY") {
      seen["target"] = Condition{"Only the target's direction is known.", found};
    } else if (startsWith(part, "silent inputs: ")) {
      for (const std::string& topic : split(part.substr(15), ", ")) {
        const std::string words = spokenLabel(topic);
        seen["silent " + topic] = Condition{"Locator: no data from " + words + ".",
                                            "Locator: data from " + words + " again.", 1};
      }
    } else {
      seen["warn " + part] = Condition{"Locator: " + part + ".", "", 2};
    }
  }
  return seen;
}

bool FaultSpeech::observe(const ReportedStatus& status, double now) {
  const std::string name = speakerName(status);
  if (name.empty()) {
    return false;
  }
  Source& source = sources_[status.name];
  source.name = name;
  source.locator = name == "Locator";
  source.last_report = now;
  update(source, source.locator ? locatorConditions(status) : driverConditions(source, status),
         now);
  return true;
}

void FaultSpeech::update(Source& source, std::map<std::string, Condition> seen, double now) {
  for (auto& entry : seen) {
    const auto it = source.conditions.find(entry.first);
    if (it == source.conditions.end()) {
      entry.second.since = now;
      source.conditions.emplace(entry.first, std::move(entry.second));
      continue;
    }
    Condition& c = it->second;
    if (c.onset != entry.second.onset) {  // e.g. the target went from lost to uncertain
      c.onset = entry.second.onset;
      c.recovery = entry.second.recovery;
      c.spoken = false;
      c.present = true;
      c.since = now;
    } else if (!c.present) {  // back before its end was said: nothing new to say
      c.present = true;
      c.since = now;
    }
  }
  for (auto& entry : source.conditions) {
    if (entry.second.present && seen.count(entry.first) == 0) {
      entry.second.present = false;
      entry.second.since = now;
    }
  }
}

std::vector<std::string> FaultSpeech::due(double now) {
  for (auto& entry : sources_) {
    Source& source = entry.second;
    const auto stale = source.conditions.find("stale");
    const bool is_stale = stale != source.conditions.end() && stale->second.present;
    if (!is_stale && now - source.last_report > params_.silence_timeout) {
      // The node stopped reporting: what it said last no longer tells anything, and
      // no "back" is owed for it.
      source.conditions.clear();
      Condition c{source.name + " stopped reporting.", source.name + " reporting again."};
      c.since = now;
      source.conditions.emplace("stale", std::move(c));
    }
  }
  struct Said {
    double since;
    int rank;
    std::string text;
  };
  std::vector<Said> said;
  for (auto& entry : sources_) {
    auto& conditions = entry.second.conditions;
    for (auto it = conditions.begin(); it != conditions.end();) {
      Condition& c = it->second;
      const bool held = now - c.since >= params_.hold_time;
      if (c.present && held && !c.spoken) {
        c.spoken = true;
        c.owed = c.owed || !c.recovery.empty();
        said.push_back({c.since, c.rank, c.onset});
      } else if (!c.present && held) {
        if (c.owed && !c.recovery.empty()) {
          said.push_back({c.since, c.rank, c.recovery});
        }
        it = conditions.erase(it);
        continue;
      }
      ++it;
    }
  }
  std::stable_sort(said.begin(), said.end(), [](const Said& a, const Said& b) {
    return a.since < b.since || (a.since == b.since && a.rank < b.rank);
  });
  std::vector<std::string> texts;
  for (auto& s : said) {
    texts.push_back(std::move(s.text));
  }
  return texts;
}

}  // namespace control
}  // namespace radio_follow
