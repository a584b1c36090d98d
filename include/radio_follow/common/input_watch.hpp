// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace radio_follow {

/// Watches the inputs a node expects (e.g. the locator's per-sensor topics) for silence:
/// an input that has never delivered within `timeout` seconds of the start, or whose last
/// message is older than `timeout`, is silent. Warnings are rationed per input, at most
/// one per `warn_period` seconds each. Times are seconds on one clock (the node's).
class InputWatch {
 public:
  struct Input {
    std::string name;           ///< what a user sees: the fully resolved topic
    double last_time = -1.0;    ///< s, last message; < 0 = never
    std::size_t messages = 0;   ///< received so far
    double last_warned = -1.0;  ///< s, last warning about it; < 0 = never
  };

  /// Starts the watch at `now` with one input per name.
  InputWatch(const std::vector<std::string>& names, double timeout, double warn_period, double now);

  /// A message arrived on input `index` at `now`. Returns true for its first message
  /// (the node logs that once).
  bool onMessage(std::size_t index, double now);

  /// Whether input `index` is silent at `now`.
  bool silent(std::size_t index, double now) const;
  /// Indices of the silent inputs at `now`.
  std::vector<std::size_t> silentInputs(double now) const;
  /// The silent inputs due for a warning at `now` (none warned within warn_period); marks
  /// them warned.
  std::vector<std::size_t> dueWarnings(double now);

  /// Seconds input `index` has been silent at `now`: since its last message, or since the
  /// start when it never delivered.
  double silenceSeconds(std::size_t index, double now) const;

  const std::vector<Input>& inputs() const { return inputs_; }
  double timeout() const { return timeout_; }
  /// Moves the start to `now` (the node's clock began only after construction), keeping
  /// what was received.
  void startAt(double now) { start_ = now; }
  /// Restarts the clock (e.g. after the clock jumped back): every input is new again.
  void restart(double now);

 private:
  std::vector<Input> inputs_;
  double timeout_;
  double warn_period_;
  double start_;
};

}  // namespace radio_follow
