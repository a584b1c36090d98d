// SPDX-License-Identifier: BSD-3-Clause
// Loading and validating the simulator node's parameters (split from the node's wiring).
#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/sim/simulator_node.hpp"

namespace radio_follow {
namespace {

double xmlNumber(XmlRpc::XmlRpcValue& v, const std::string& name) {
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
    return static_cast<double>(v);
  }
  if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    return static_cast<int>(v);
  }
  throw ParamError(name, v.toXml(), "a number");
}

/// `~twr_occlusions`: a list of {module, bearing_min_deg, bearing_max_deg, extra_range,
/// probability}; see config/simulator.yaml.
std::vector<sim::OcclusionSector> loadOcclusions(const ParamReader& pnh) {
  std::vector<sim::OcclusionSector> sectors;
  XmlRpc::XmlRpcValue list;
  if (!pnh.getRaw("twr_occlusions", list)) {
    return sectors;
  }
  if (list.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw ParamError("~twr_occlusions", list.toXml(), "a list of occlusion sectors");
  }
  for (int i = 0; i < list.size(); ++i) {
    const std::string name = "~twr_occlusions[" + std::to_string(i) + "]";
    XmlRpc::XmlRpcValue& item = list[i];
    if (item.getType() != XmlRpc::XmlRpcValue::TypeStruct || !item.hasMember("bearing_min_deg") ||
        !item.hasMember("bearing_max_deg")) {
      throw ParamError(name, item.toXml(),
                       "{module, bearing_min_deg, bearing_max_deg, extra_range, probability}");
    }
    requireMembers(
        item, {"module", "bearing_min_deg", "bearing_max_deg", "extra_range", "probability"}, name);
    sim::OcclusionSector s;
    if (item.hasMember("module")) {
      if (item["module"].getType() != XmlRpc::XmlRpcValue::TypeString) {
        throw ParamError(name + ".module", item["module"].toXml(), "a TWR module ID string");
      }
      s.module = static_cast<std::string>(item["module"]);
    }
    s.bearing_min = deg2rad(xmlNumber(item["bearing_min_deg"], name + ".bearing_min_deg"));
    s.bearing_max = deg2rad(xmlNumber(item["bearing_max_deg"], name + ".bearing_max_deg"));
    if (item.hasMember("extra_range")) {
      s.reflection_extra = xmlNumber(item["extra_range"], name + ".extra_range");
    }
    if (item.hasMember("probability")) {
      s.reflection_probability = xmlNumber(item["probability"], name + ".probability");
    }
    sectors.push_back(s);
  }
  return sectors;
}

/// `~unplug`: a list of {device, at, duration} (serial mode only).
std::vector<sim::UnplugFault> loadUnplugFaults(const ParamReader& pnh) {
  std::vector<sim::UnplugFault> faults;
  XmlRpc::XmlRpcValue list;
  if (!pnh.getRaw("unplug", list)) {
    return faults;
  }
  if (list.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw ParamError("~unplug", list.toXml(), "a list of {device, at, duration}");
  }
  for (int i = 0; i < list.size(); ++i) {
    const std::string name = "~unplug[" + std::to_string(i) + "]";
    XmlRpc::XmlRpcValue& item = list[i];
    if (item.getType() != XmlRpc::XmlRpcValue::TypeStruct || !item.hasMember("device") ||
        item["device"].getType() != XmlRpc::XmlRpcValue::TypeString || !item.hasMember("at") ||
        !item.hasMember("duration")) {
      throw ParamError(name, item.toXml(), "{device: uwb_<id> | aoa_<id>, at: s, duration: s}");
    }
    requireMembers(item, {"device", "at", "duration"}, name);
    faults.push_back(sim::UnplugFault{static_cast<std::string>(item["device"]),
                                      xmlNumber(item["at"], name + ".at"),
                                      xmlNumber(item["duration"], name + ".duration")});
  }
  return faults;
}

}  // namespace

SimulatorNode::Params loadSimulatorParams(const ParamReader& pnh) {
  SimulatorNode::Params p;
  SimulatorNode::Params::table().load(pnh, p);
  p.world.seed = static_cast<std::uint64_t>(std::max(0, p.seed));
  p.world.twr.occlusions = loadOcclusions(pnh);
  p.unplug = loadUnplugFaults(pnh);
  p.validate();
  return p;
}

}  // namespace radio_follow
