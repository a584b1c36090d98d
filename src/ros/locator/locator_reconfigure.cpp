// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/locator/locator_reconfigure.hpp"

#include <string>
#include <utility>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {

LocatorTuningConfig toTuning(const estimation::LocatorConfig& c) {
  LocatorTuningConfig t = LocatorTuningConfig::__getDefault__();
  t.target_height = c.height;
  t.default_range = c.default_range;
  t.range_sigma = c.range_sigma;
  t.tdoa_sigma = c.tdoa_sigma;
  t.azimuth_sigma_deg = rad2deg(c.azimuth_sigma);
  t.elevation_sigma_deg = rad2deg(c.elevation_sigma);
  t.use_elevation = c.use_elevation;
  t.max_age = c.max_age;
  t.range_loss = toString(c.range_loss.type);
  t.range_loss_scale = c.range_loss.scale;
  t.tdoa_loss = toString(c.tdoa_loss.type);
  t.tdoa_loss_scale = c.tdoa_loss.scale;
  t.bearing_loss = toString(c.bearing_loss.type);
  t.bearing_loss_scale = c.bearing_loss.scale;
  t.aoa_selection = toString(c.aoa.mode);
  t.aoa_rssi_window = static_cast<int>(c.aoa.rssi_window);
  t.aoa_vote_window = static_cast<int>(c.aoa.vote_window);
  t.motion_model = toString(c.motion_model);
  t.process_noise = c.process_noise;
  t.measurement_covariance = c.filter_uses_solver_covariance ? "solver" : "fixed";
  t.measurement_noise = c.measurement_noise;
  t.gate_probability = c.gate_probability;
  t.max_consecutive_rejections = c.max_consecutive_rejections;
  t.ceres_covariance = c.ceres_covariance;
  t.max_position_sigma = c.max_position_sigma;
  t.max_relative_sigma = c.max_relative_sigma;
  t.ambiguity_margin = c.ambiguity_margin;
  return t;
}

estimation::LocatorConfig fromTuning(const LocatorTuningConfig& t, estimation::LocatorConfig c) {
  c.height = t.target_height;
  c.default_range = t.default_range;
  c.range_sigma = t.range_sigma;
  c.tdoa_sigma = t.tdoa_sigma;
  c.azimuth_sigma = deg2rad(t.azimuth_sigma_deg);
  c.elevation_sigma = deg2rad(t.elevation_sigma_deg);
  c.use_elevation = t.use_elevation;
  c.max_age = t.max_age;
  c.range_loss = {estimation::parseLossType(t.range_loss, "~range_loss"), t.range_loss_scale};
  c.tdoa_loss = {estimation::parseLossType(t.tdoa_loss, "~tdoa_loss"), t.tdoa_loss_scale};
  c.bearing_loss = {estimation::parseLossType(t.bearing_loss, "~bearing_loss"),
                    t.bearing_loss_scale};
  c.aoa.mode = estimation::parseAoaSelectionMode(t.aoa_selection, "~aoa_selection");
  // The windows are counts: a negative request must fail validation, not wrap around.
  require(t.aoa_rssi_window >= 1, "aoa_rssi_window", t.aoa_rssi_window, "at least 1");
  require(t.aoa_vote_window >= 1, "aoa_vote_window", t.aoa_vote_window, "at least 1");
  c.aoa.rssi_window = static_cast<std::size_t>(t.aoa_rssi_window);
  c.aoa.vote_window = static_cast<std::size_t>(t.aoa_vote_window);
  c.motion_model = estimation::parseMotionModel(t.motion_model, "~motion_model");
  c.process_noise = t.process_noise;
  require(t.measurement_covariance == "fixed" || t.measurement_covariance == "solver",
          "~measurement_covariance", t.measurement_covariance, "fixed or solver");
  c.filter_uses_solver_covariance = t.measurement_covariance == "solver";
  c.measurement_noise = t.measurement_noise;
  c.gate_probability = t.gate_probability;
  c.max_consecutive_rejections = t.max_consecutive_rejections;
  c.ceres_covariance = t.ceres_covariance;
  c.max_position_sigma = t.max_position_sigma;
  c.max_relative_sigma = t.max_relative_sigma;
  c.ambiguity_margin = t.ambiguity_margin;
  return c;
}

std::unique_ptr<LocatorReconfigure> makeLocatorReconfigure(
    const ros::NodeHandle& private_nh, const estimation::LocatorConfig& initial,
    std::function<void(const estimation::LocatorConfig&)> apply) {
  return std::make_unique<LocatorReconfigure>(private_nh, initial, toTuning, fromTuning,
                                              std::move(apply));
}

}  // namespace radio_follow
