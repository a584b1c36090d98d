// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <string_view>

namespace radio_follow::drivers {

/// The DWM1001 UART shell dialogue as a pure state machine: no I/O and no clock of its
/// own, so every step is unit-testable. The owner feeds it the connection event, each
/// received line, the pending partial line (the prompt "dwm> " has no newline) and the
/// time, and writes whatever text the returned strings hold to the device.
///
/// Sequence: "\r\r" (two carriage returns switch a module from its binary API to the
/// shell; on a module already in the shell, or streaming, they stop the stream and
/// print prompts) -> wait for "dwm>" -> "si\r" -> wait for `label=DW<id>` -> wait for
/// the prompt -> stream command ("lec\r"/"les\r"/"lep\r") -> streaming. A step that
/// sees no answer within `step_timeout` restarts the sequence.
class Dwm1001Shell {
 public:
  enum class State { kDisconnected, kWaitPrompt, kWaitLabel, kWaitPromptAfterInfo, kStreaming };

  /// `stream_command` is "lec", "les" or "lep"; `step_timeout` in seconds.
  Dwm1001Shell(std::string stream_command, double step_timeout);

  /// Device (re)opened at time `now`: returns the wake-up text to send.
  std::string onConnected(double now);
  /// Device lost.
  void onDisconnected();
  /// A complete line arrived; returns text to send (possibly empty).
  std::string onLine(std::string_view line, double now);
  /// Bytes received after the last line end, e.g. "dwm> "; returns text to send.
  std::string onPending(std::string_view pending, double now);
  /// Periodic check; returns text to send when a step timed out.
  std::string onTick(double now);
  /// The streaming module has been silent too long (e.g. it reset and fell back to its
  /// binary API): returns the wake-up text and restarts the dialogue; nothing otherwise.
  std::string onSilence(double now);
  /// Text that stops the stream and leaves the shell (sent on shutdown). The stream
  /// commands toggle, so sending the same one again stops it.
  std::string stopText() const;

  State state() const { return state_; }
  /// Module ID from the `si` label (e.g. "5722"); empty until read.
  const std::string& tagId() const { return tag_id_; }
  /// Number of times a step timed out and the dialogue restarted.
  unsigned restarts() const { return restarts_; }

  /// Extracts "5722" from a line containing "label=DW5722" (also without "DW").
  static std::string parseLabel(std::string_view line);

 private:
  std::string onPrompt(double now);
  std::string enter(State state, double now, std::string text);

  std::string stream_command_;
  double step_timeout_;
  State state_ = State::kDisconnected;
  double step_start_ = 0.0;
  std::string tag_id_;
  unsigned restarts_ = 0;
};

}  // namespace radio_follow::drivers
