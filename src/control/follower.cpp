// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/follower.hpp"

#include <stdexcept>

namespace radio_follow {
namespace control {

Follower::Follower(const CommandPipelineParams& params) : pipeline_(params) {}

EstimateUse Follower::onEstimate(double stamp, double now, TargetStatus status, double range,
                                 double bearing, const PolarSpread& spread, int hypotheses) {
  if (!pipeline_.onEstimate(stamp, now, estimateQuality(status, range, bearing))) {
    return EstimateUse::kRefused;  // nothing of it reaches the law or the track
  }
  target_ = targetPolar(status, range, bearing, spread, hypotheses, std::nullopt, 0.0);
  return gate_.accept(status) ? EstimateUse::kTrackPoint : EstimateUse::kHeard;
}

bool Follower::addTrackPoint(double stamp, const TrackPoint& point) {
  return track_.add(stamp, point) && law_ != nullptr && law_->addTrackPoint(point.target);
}

PipelineResult Follower::tick(double now, double dt, const std::optional<Pose2>& robot) {
  if (law_ == nullptr) {
    throw std::logic_error("Follower::tick() before setLaw()");
  }
  const SafetyDecision decision = pipeline_.check(now);
  if (!decision.may_move) {
    return stop(decision.reason);
  }
  FollowInput input;
  input.now = now;
  input.robot = robot;
  input.walking_speed = track_.speed(now);
  if (target_) {
    input.target = *target_;
    input.target->receding_speed = track_.recedingSpeed(now).value_or(0.0);
    input.target->module_gap = pipeline_.moduleGap(now);
  }
  return pipeline_.finish(law_->step(input, dt), now, dt);
}

PipelineResult Follower::stop(StopReason reason) {
  if (law_ != nullptr) {
    law_->onStopped();
  }
  return pipeline_.stop(reason);
}

void Follower::setCommon(const CommandPipelineParams& params) {
  if (law_ != nullptr) {
    law_->setCommon(params);  // throws to refuse before the pipeline changes
  }
  pipeline_.setParams(params);
}

}  // namespace control
}  // namespace radio_follow
