// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/velocity_controller.hpp"

#include "radio_follow/ros/control/controller_reconfigure.hpp"

namespace radio_follow {

VelocityControllerNode::VelocityControllerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : EstimateFollowerNode(nh, private_nh), law_(loadVelocityLawParams(params(), common())) {
  requireKnownParams();
  // Speed caps come from the common limits; the law's own fields are tuned on ~law.
  law_reconfigure_ = makeFollowLawReconfigure(private_nh, law_.params(),
                                              [this](const control::VelocityLawParams& p) {
                                                // The server's copy of the common values may be
                                                // older than a change on ~: check the law against
                                                // the safety layer as it is now (throws ParamError
                                                // to refuse).
                                                law_.setParams(lawWithCommon(p, common()));
                                              });
  startFollowing(law_);
}

VelocityControllerNode::~VelocityControllerNode() = default;

}  // namespace radio_follow
