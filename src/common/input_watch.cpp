// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/input_watch.hpp"

namespace radio_follow {

InputWatch::InputWatch(const std::vector<std::string>& names, double timeout, double warn_period,
                       double now)
    : timeout_(timeout), warn_period_(warn_period), start_(now) {
  for (const std::string& name : names) {
    inputs_.push_back(Input{name});
  }
}

bool InputWatch::onMessage(std::size_t index, double now) {
  Input& input = inputs_.at(index);
  input.last_time = now;
  return ++input.messages == 1;
}

double InputWatch::silenceSeconds(std::size_t index, double now) const {
  const Input& input = inputs_.at(index);
  return now - (input.messages > 0 ? input.last_time : start_);
}

bool InputWatch::silent(std::size_t index, double now) const {
  return silenceSeconds(index, now) > timeout_;
}

std::vector<std::size_t> InputWatch::silentInputs(double now) const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    if (silent(i, now)) {
      out.push_back(i);
    }
  }
  return out;
}

std::vector<std::size_t> InputWatch::dueWarnings(double now) {
  std::vector<std::size_t> out;
  for (const std::size_t i : silentInputs(now)) {
    Input& input = inputs_[i];
    if (input.last_warned < 0.0 || now - input.last_warned >= warn_period_) {
      input.last_warned = now;
      out.push_back(i);
    }
  }
  return out;
}

void InputWatch::restart(double now) {
  start_ = now;
  for (Input& input : inputs_) {
    input.last_time = input.last_warned = -1.0;
    input.messages = 0;
  }
}

}  // namespace radio_follow
