// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/publisher.h>
#include <ros/ros.h>

#include <memory>
#include <mutex>
#include <string>

namespace radio_follow {

/// Rate and stamp-age diagnostic of one output topic, added to a node's updater as
/// "<label> <resolved topic> topic status": WARN when the publishing rate over the last
/// 5 s leaves [min_hz, max_hz] (+-10 %) or, for stamped messages, when a stamp's age at
/// publishing leaves [min_age, max_age] s (negative: stamped in the future). Call tick()
/// for every published message; it is thread-safe (the drivers publish from their
/// delivery thread). The bounds come from the node's own configured rates and timeouts.
class OutputDiagnostic {
 public:
  struct Bounds {
    double min_hz = 0.0;
    double max_hz = 1e9;
    double min_age = -1.0;  ///< s
    double max_age = 5.0;   ///< s

    /// A driver's output: at least one message per `silence_timeout`, at most the device's
    /// `max_hz`; stamps are the host's receive time, so one older than silence_timeout at
    /// publishing sat that long in the queue.
    static Bounds forDriver(double silence_timeout, double max_hz);
  };

  /// `stamped` = the messages have a header: the stamp's age is checked too. An output
  /// with no lower rate (`min_hz` 0: it may have nothing to say, like a module's own
  /// position) gets its status only once it has published: before, diagnostic_updater
  /// would report ERROR "No events recorded" for an output that is fine unused.
  OutputDiagnostic(diagnostic_updater::Updater& updater, const std::string& label,
                   const ros::Publisher& publisher, const Bounds& bounds, bool stamped);
  OutputDiagnostic(const OutputDiagnostic&) = delete;  // the updater holds pointers into it
  OutputDiagnostic& operator=(const OutputDiagnostic&) = delete;

  /// Stamped topics: one message with this header stamp was published.
  void tick(const ros::Time& stamp);
  /// Headerless topics: one message was published.
  void tick();

 private:
  void create();

  diagnostic_updater::Updater& updater_;
  std::string name_;
  bool stamped_output_;
  std::once_flag created_;
  Bounds bounds_;  // FrequencyStatusParam keeps pointers to min_hz / max_hz
  std::unique_ptr<diagnostic_updater::TopicDiagnostic> stamped_;
  std::unique_ptr<diagnostic_updater::HeaderlessTopicDiagnostic> headerless_;
};

}  // namespace radio_follow
