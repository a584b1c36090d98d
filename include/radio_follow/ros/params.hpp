// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <ros/ros.h>

#include <string>
#include <vector>

namespace radio_follow {

/// Reads the private parameter `name` as a list of strings into `out` (unchanged when
/// unset). Unlike NodeHandle::param it throws ParamError for a value of the wrong type
/// instead of silently keeping the default: these lists decide what a node listens to.
void loadStringList(const ros::NodeHandle& private_nh, const std::string& name,
                    std::vector<std::string>& out);

/// A node's parameter struct loaded from the private namespace and validated (throws
/// ParamError naming the first bad parameter), for a constructor's initialiser list.
template <typename Params>
Params loadValidated(const ros::NodeHandle& private_nh) {
  Params p;
  p.load(private_nh);
  p.validate();
  return p;
}

}  // namespace radio_follow
