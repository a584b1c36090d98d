// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/params.hpp"

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {

void loadStringList(const ros::NodeHandle& private_nh, const std::string& name,
                    std::vector<std::string>& out) {
  XmlRpc::XmlRpcValue value;
  if (!private_nh.getParam(name, value)) {
    return;
  }
  require(value.getType() == XmlRpc::XmlRpcValue::TypeArray, "~" + name,
          std::string("a non-list value"), "a list of topic names");
  std::vector<std::string> list;
  for (int i = 0; i < value.size(); ++i) {
    require(value[i].getType() == XmlRpc::XmlRpcValue::TypeString, "~" + name,
            std::string("a list with a non-string element"), "a list of topic names");
    list.push_back(static_cast<std::string>(value[i]));
  }
  out = list;
}

}  // namespace radio_follow
