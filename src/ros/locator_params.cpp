// SPDX-License-Identifier: BSD-3-Clause
#include <cmath>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/ros/locator_node.hpp"  // declares LocatorNode::Params
#include "radio_follow/ros/yaml_params.hpp"

namespace radio_follow {
namespace {

template <typename Source>
LossConfig loadLoss(const Source& nh, const std::string& name, const LossConfig& def) {
  std::string type = toString(def.type);
  LossConfig loss = def;
  nh.param(name, type, type);
  nh.param(name + "_scale", loss.scale, loss.scale);
  loss.type = parseLossType(type, "~" + name);
  return loss;
}

}  // namespace

template <typename Source>
void LocatorNode::Params::load(const Source& nh) {
  nh.param("layout_file", layout_file, layout_file);
  nh.param("uwb_topics", uwb_topics, uwb_topics);
  nh.param("aoa_topics", aoa_topics, aoa_topics);
  nh.param("tdoa_topics", tdoa_topics, tdoa_topics);
  nh.param("rate", rate, rate);
  nh.param("target_frame", target_frame, target_frame);
  nh.param("publish_tf", publish_tf, publish_tf);
  nh.param("input_timeout", input_timeout, input_timeout);
  nh.param("path_length", path_length, path_length);

  LocatorConfig& c = locator;
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

template void LocatorNode::Params::load(const ParamReader&);
template void LocatorNode::Params::load(const YamlParams&);

void LocatorNode::Params::validate() const {
  require(!layout_file.empty(), "~layout_file", layout_file, "the path of a layout YAML file");
  // All topic lists empty is fine: the node then uses the layout's conventional topics.
  require(std::isfinite(rate) && rate > 0.0 && rate <= 200.0, "~rate", rate,
          "a solve rate in (0, 200] Hz");
  require(!target_frame.empty(), "~target_frame", target_frame, "a frame name");
  require(std::isfinite(input_timeout) && input_timeout > 0.0 && input_timeout <= 600.0,
          "~input_timeout", input_timeout, "seconds in (0, 600]");
  require(path_length >= 0 && path_length <= 100000, "~path_length", path_length,
          "a number of estimates in [0, 100000] (0 = no path)");
  locator.validate();  // the core names its fields exactly like these private parameters
}

}  // namespace radio_follow
