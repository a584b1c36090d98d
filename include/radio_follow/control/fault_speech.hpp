// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace radio_follow {
namespace control {

/// Severity of a reported status; the values of diagnostic_msgs/DiagnosticStatus.
enum class StatusLevel : std::uint8_t { kOk = 0, kWarn = 1, kError = 2, kStale = 3 };

/// One entry of a diagnostics report, as the drivers and the locator publish it on
/// /diagnostics (doc/diagnostics.md): name "<node>: <task>", level, summary message and
/// hardware_id.
struct ReportedStatus {
  std::string name;
  StatusLevel level = StatusLevel::kOk;
  std::string message;
  std::string hardware_id;
};

/// When a reported fault is worth saying.
struct FaultSpeechParams {
  /// A fault (or its end) is spoken once it has held this long: one dropped diagnostics
  /// cycle or a flapping input says nothing. s
  double hold_time = 2.0;
  /// A source that reported before and has not reported for this long has stopped (its
  /// node died or hangs). s
  double silence_timeout = 5.0;

  /// Throws ParamError naming the first unusable field (`prefix` + its name).
  void validate(const std::string& prefix = "") const;
};

/// Turns the drivers' and the locator's diagnostics into short sentences a person near
/// the robot can hear (thesis Section 4.8 speaks the controller's state; this adds the
/// faults under it): a device lost, silent or back, the target lost, uncertain or found,
/// a locator input silent, a node that stopped reporting.
///
/// Each report is reduced to a set of conditions (a key and the sentence that announces
/// it). A condition is spoken when it has been present for `hold_time`; when a spoken
/// condition has been absent for `hold_time`, its end is spoken. Controllers' own
/// statuses and topic-rate entries are not faults of a device or the estimate: they are
/// ignored (the controllers speak their state on their status topics).
class FaultSpeech {
 public:
  explicit FaultSpeech(const FaultSpeechParams& params);

  /// Takes one report received at `now` (s, monotonic). Reports of unknown sources are
  /// ignored; returns whether the report was used.
  bool observe(const ReportedStatus& status, double now);

  /// Sentences that became due by `now`, in the order their conditions arose.
  std::vector<std::string> due(double now);

  /// The spoken name of a source ("UWB module 5722", "AoA board front", "TDoA anchors",
  /// "Locator"), or empty when `status` is not from a driver or the locator.
  static std::string speakerName(const ReportedStatus& status);

 private:
  struct Condition {
    Condition() = default;
    Condition(std::string onset_text, std::string recovery_text, int order = 0)
        : onset(std::move(onset_text)), recovery(std::move(recovery_text)), rank(order) {}

    std::string onset;     // said when it has held for hold_time
    std::string recovery;  // said when it has been gone for hold_time after being spoken
    int rank = 0;          // order among conditions of the same moment: the state first
    double since = 0.0;    // first seen (present) or last seen (absent)
    bool present = true;
    bool spoken = false;  // this onset was said
    bool owed = false;    // an onset of this key was said, its recovery not yet
  };
  struct Source {
    std::string name;  // spoken
    bool locator = false;
    double last_report = 0.0;
    std::map<std::string, Condition> conditions;  // by key
  };

  void update(Source& source, std::map<std::string, Condition> seen, double now);
  static std::map<std::string, Condition> driverConditions(const Source& source,
                                                           const ReportedStatus& status);
  static std::map<std::string, Condition> locatorConditions(const ReportedStatus& status);

  FaultSpeechParams params_;
  std::map<std::string, Source> sources_;  // by status name
};

}  // namespace control
}  // namespace radio_follow
