// SPDX-License-Identifier: BSD-3-Clause
// Loading the locator's tuning from a ParamSource (the node's private parameters or a
// YAML file): the names are the node's parameters (doc/nodes/locator.md).
#include <string>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/locator.hpp"

namespace radio_follow {
namespace estimation {
namespace {

LossConfig loadLoss(const ParamSource& nh, const std::string& name, const LossConfig& def) {
  std::string type = toString(def.type);
  LossConfig loss = def;
  nh.param(name, type, type);
  nh.param(name + "_scale", loss.scale, loss.scale);
  loss.type = parseLossType(type, "~" + name);
  return loss;
}

}  // namespace

void LocatorConfig::load(const ParamSource& nh) {
  LocatorConfig& c = *this;
  std::string mode = c.planar ? "2d" : "3d";
  nh.param("mode", mode, mode);
  require(mode == "2d" || mode == "3d", "~mode", mode, "2d or 3d");
  c.planar = mode == "2d";
  nh.param("target_height", c.height, c.height);
  nh.param("range_sigma", c.range_sigma, c.range_sigma);
  nh.param("tdoa_sigma", c.tdoa_sigma, c.tdoa_sigma);
  double az_deg = rad2deg(c.azimuth_sigma);
  double el_deg = rad2deg(c.elevation_sigma);
  nh.param("azimuth_sigma_deg", az_deg, az_deg);
  nh.param("elevation_sigma_deg", el_deg, el_deg);
  c.azimuth_sigma = deg2rad(az_deg);
  c.elevation_sigma = deg2rad(el_deg);
  nh.param("use_elevation", c.use_elevation, c.use_elevation);
  c.range_loss = loadLoss(nh, "range_loss", c.range_loss);
  c.tdoa_loss = loadLoss(nh, "tdoa_loss", c.tdoa_loss);
  c.bearing_loss = loadLoss(nh, "bearing_loss", c.bearing_loss);
  nh.param("max_age", c.max_age, c.max_age);

  std::string selection = toString(c.aoa.mode);
  nh.param("aoa_selection", selection, selection);
  c.aoa.mode = parseAoaSelectionMode(selection, "~aoa_selection");
  int rssi_window = static_cast<int>(c.aoa.rssi_window);
  int vote_window = static_cast<int>(c.aoa.vote_window);
  nh.param("aoa_rssi_window", rssi_window, rssi_window);
  nh.param("aoa_vote_window", vote_window, vote_window);
  require(rssi_window >= 1, "~aoa_rssi_window", rssi_window, "at least 1");
  require(vote_window >= 1, "~aoa_vote_window", vote_window, "at least 1");
  c.aoa.rssi_window = static_cast<std::size_t>(rssi_window);
  c.aoa.vote_window = static_cast<std::size_t>(vote_window);

  std::string model = toString(c.motion_model);
  nh.param("motion_model", model, model);
  c.motion_model = parseMotionModel(model, "~motion_model");
  nh.param("process_noise", c.process_noise, c.process_noise);
  std::string r_source = c.filter_uses_solver_covariance ? "solver" : "fixed";
  nh.param("measurement_covariance", r_source, r_source);
  require(r_source == "fixed" || r_source == "solver", "~measurement_covariance", r_source,
          "fixed or solver");
  c.filter_uses_solver_covariance = r_source == "solver";
  nh.param("measurement_noise", c.measurement_noise, c.measurement_noise);
  nh.param("gate_probability", c.gate_probability, c.gate_probability);
  nh.param("max_consecutive_rejections", c.max_consecutive_rejections,
           c.max_consecutive_rejections);
  nh.param("ceres_covariance", c.ceres_covariance, c.ceres_covariance);
  nh.param("max_position_sigma", c.max_position_sigma, c.max_position_sigma);
  nh.param("max_relative_sigma", c.max_relative_sigma, c.max_relative_sigma);
  nh.param("ambiguity_margin", c.ambiguity_margin, c.ambiguity_margin);
  nh.param("default_range", c.default_range, c.default_range);
}

}  // namespace estimation
}  // namespace radio_follow
