// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/dwm1001_shell.hpp"

#include <utility>

#include "radio_follow/drivers/dwm1001_decoder.hpp"

namespace radio_follow::drivers {
namespace {

constexpr std::string_view kLabel = "label=";

bool isPrompt(std::string_view text) {
  while (!text.empty() && text.front() == ' ') {
    text.remove_prefix(1);
  }
  return text.substr(0, kDwmPrompt.size()) == kDwmPrompt;
}

}  // namespace

Dwm1001Shell::Dwm1001Shell(std::string stream_command, double step_timeout)
    : stream_command_(std::move(stream_command)), step_timeout_(step_timeout) {}

std::string Dwm1001Shell::enter(State state, double now, std::string text) {
  state_ = state;
  step_start_ = now;
  return text;
}

std::string Dwm1001Shell::onConnected(double now) {
  return enter(State::kWaitPrompt, now, "\r\r");
}

void Dwm1001Shell::onDisconnected() {
  state_ = State::kDisconnected;
}

std::string Dwm1001Shell::onPrompt(double now) {
  switch (state_) {
    case State::kWaitPrompt:
      return enter(State::kWaitLabel, now, "si\r");
    case State::kWaitPromptAfterInfo:
      return enter(State::kStreaming, now, stream_command_ + "\r");
    default:
      return {};
  }
}

std::string Dwm1001Shell::onLine(std::string_view line, double now) {
  if (state_ == State::kWaitLabel) {
    std::string id = parseLabel(line);
    if (!id.empty()) {
      tag_id_ = std::move(id);
      return enter(State::kWaitPromptAfterInfo, now, {});
    }
    return {};
  }
  // A bare prompt line ("dwm> " followed by a newline) counts as a prompt; an echo
  // such as "dwm> si" is the prompt of the previous step and is skipped by the states.
  if (isPrompt(line) && line.find_first_not_of(' ', line.find('>') + 1) == std::string_view::npos) {
    return onPrompt(now);
  }
  return {};
}

std::string Dwm1001Shell::onPending(std::string_view pending, double now) {
  if (isPrompt(pending) &&
      pending.find_first_not_of(' ', pending.find('>') + 1) == std::string_view::npos) {
    return onPrompt(now);
  }
  return {};
}

std::string Dwm1001Shell::onTick(double now) {
  if (state_ == State::kDisconnected || state_ == State::kStreaming ||
      now - step_start_ < step_timeout_) {
    return {};
  }
  ++restarts_;
  return enter(State::kWaitPrompt, now, "\r\r");
}

std::string Dwm1001Shell::onSilence(double now) {
  if (state_ != State::kStreaming) {
    return {};  // the other states have their own step timeout
  }
  ++restarts_;
  return enter(State::kWaitPrompt, now, "\r\r");
}

std::string Dwm1001Shell::stopText() const {
  return state_ == State::kStreaming ? stream_command_ + "\rquit\r" : std::string("quit\r");
}

std::string Dwm1001Shell::parseLabel(std::string_view line) {
  const std::size_t pos = line.find(kLabel);
  if (pos == std::string_view::npos) {
    return {};
  }
  std::string_view value = line.substr(pos + kLabel.size());
  value = value.substr(0, value.find_first_of(" \t,"));
  if (value.substr(0, 2) == "DW") {
    value.remove_prefix(2);
  }
  return std::string(value);
}

}  // namespace radio_follow::drivers
