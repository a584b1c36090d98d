// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/control/velocity_controller.hpp"

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/geometry.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/control/follow_inputs.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/common/target_estimate.hpp"
#include "radio_follow/ros/control/controller_reconfigure.hpp"

namespace radio_follow {

control::TargetPolar targetPolar(const TargetEstimate& estimate,
                                 std::optional<double> receding_speed, double module_gap) {
  const auto& c = estimate.position_covariance;  // row-major 3x3
  Eigen::Matrix2d covariance;
  covariance << c[0], c[1], c[3], c[4];
  const PolarSpread spread =
      polarSpread(Eigen::Vector2d(estimate.position.x, estimate.position.y), covariance);
  return control::targetPolar(static_cast<TargetStatus>(estimate.status), estimate.range,
                              estimate.bearing, spread, estimate.hypotheses, receding_speed,
                              module_gap);
}

void VelocityControllerNode::Params::load(const ParamReader& pnh) {
  pnh.param("odom_frame", odom_frame, odom_frame);
  pnh.param("tf_timeout", tf_timeout, tf_timeout);
}

void VelocityControllerNode::Params::validate() const {
  require(tf_timeout >= 0.0 && tf_timeout < 1.0, "~tf_timeout", tf_timeout,
          "a timeout in [0, 1) seconds");
}

VelocityControllerNode::VelocityControllerNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : ControllerBase(nh, private_nh, true),
      params_(loadValidated<Params>(params())),
      law_(loadVelocityLawParams(params(), common())),
      tf_listener_(tf_buffer_),
      motion_(tf_buffer_, params_.odom_frame, params_.tf_timeout) {
  requireKnownParams();
  estimate_sub_ = barrier_.subscribe(nh_, "target", 5, &VelocityControllerNode::onEstimate, this);
  debugSubscribed(estimate_sub_);
  // Speed caps come from the common limits; the law's own fields are tuned on ~law.
  law_reconfigure_ = makeFollowLawReconfigure(private_nh, law_.params(),
                                              [this](const control::VelocityLawParams& p) {
                                                // The server's copy of the common values may be
                                                // older than a change on ~: check the law against
                                                // the safety layer as it is now (throws ParamError
                                                // to refuse).
                                                law_.setParams(lawWithCommon(p, common()));
                                              });
  start();
}

VelocityControllerNode::~VelocityControllerNode() = default;

void VelocityControllerNode::onCommonChange(const ControllerCommonParams& next) {
  law_.setParams(lawWithCommon(law_.params(), next));  // throws to refuse the change
}

void VelocityControllerNode::onEstimate(const TargetEstimate::ConstPtr& msg) {
  if (!noteEstimate(msg->header.stamp, estimateQuality(*msg))) {
    return;  // from the future: the robot stops, and nothing of it reaches the law or TF
  }
  estimate_ = msg;
  if (!params_.odom_frame.empty() && !motion_.add(*msg) && !motion_.lastError().empty()) {
    ROS_WARN_THROTTLE(10.0, "%s: no transform %s <- %s, following without speed feed-forward (%s)",
                      ros::this_node::getName().c_str(), params_.odom_frame.c_str(),
                      msg->header.frame_id.c_str(), motion_.lastError().c_str());
  }
}

ControllerBase::Output VelocityControllerNode::compute(const ros::Time& now, double dt) {
  const std::optional<double> receding =
      params_.odom_frame.empty() ? std::nullopt : motion_.recedingSpeed(now);
  return law_.step(targetPolar(*estimate_, receding, moduleGap(now)), dt);
}

}  // namespace radio_follow
