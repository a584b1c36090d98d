// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/common/callback_barrier.hpp"

namespace radio_follow {

std::string CallbackBarrier::lastFault() const {
  const std::lock_guard<std::mutex> lock(last_mutex_);
  return last_;
}

void CallbackBarrier::fault(const std::string& where, const char* what) noexcept {
  try {
    ++faults_;
    {
      const std::lock_guard<std::mutex> lock(last_mutex_);
      last_ = where + ": " + what;
    }
    ROS_ERROR_THROTTLE(1.0, "%s: callback %s threw and was cut short (%s); %llu so far",
                       ros::this_node::getName().c_str(), where.c_str(), what,
                       static_cast<unsigned long long>(faults_.load()));
    if (action_) {
      action_(where, what);
    }
  } catch (const std::exception& e) {
    ROS_ERROR_THROTTLE(1.0, "%s: the fault action after %s threw too: %s",
                       ros::this_node::getName().c_str(), where.c_str(), e.what());
  } catch (...) {
    ROS_ERROR_THROTTLE(1.0, "%s: the fault action after %s threw too",
                       ros::this_node::getName().c_str(), where.c_str());
  }
}

}  // namespace radio_follow
