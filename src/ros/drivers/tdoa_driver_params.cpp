// SPDX-License-Identifier: BSD-3-Clause
// Parameter loading and validation of the TDoA driver node.
#include <xmlrpcpp/XmlRpcValue.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/ros/common/params.hpp"
#include "radio_follow/ros/drivers/tdoa_driver.hpp"

namespace radio_follow {
namespace {

double number(XmlRpc::XmlRpcValue& v, const std::string& name) {
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
    return static_cast<double>(v);
  }
  if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    return static_cast<int>(v);
  }
  throw ParamError(name, v.toXml(), "a number");
}

std::string text(XmlRpc::XmlRpcValue& v, const std::string& name, const std::string& expected) {
  if (v.getType() != XmlRpc::XmlRpcValue::TypeString) {
    throw ParamError(name, v.toXml(), expected);
  }
  return static_cast<std::string>(v);
}

// "0000000000002001", "0x2001" or "2001": hexadecimal, at most 64 bits.
std::uint64_t parseAddress(const std::string& s, const std::string& name) {
  const std::string expected = "a hexadecimal anchor address of at most 16 digits";
  std::string digits = s;
  if (digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    digits = digits.substr(2);
  }
  require(!digits.empty() && digits.size() <= 16 &&
              digits.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos,
          name, s, expected);
  return std::strtoull(digits.c_str(), nullptr, 16);
}

drivers::TdoaAnchorConfig parseAnchor(XmlRpc::XmlRpcValue& v, const std::string& name) {
  if (v.getType() != XmlRpc::XmlRpcValue::TypeStruct || !v.hasMember("id") ||
      !v.hasMember("address") || !v.hasMember("position")) {
    throw ParamError(name, v.toXml(), "a map with id, address and position");
  }
  requireMembers(v, {"id", "address", "position"}, name);
  drivers::TdoaAnchorConfig anchor;
  anchor.id = normalizeId(text(v["id"], name + ".id", "a string"));
  anchor.address =
      parseAddress(text(v["address"], name + ".address", "a hex string"), name + ".address");
  XmlRpc::XmlRpcValue& p = v["position"];
  if (p.getType() != XmlRpc::XmlRpcValue::TypeArray || p.size() != 3) {
    throw ParamError(name + ".position", p.toXml(), "a list [x, y, z] in metres");
  }
  for (int k = 0; k < 3; ++k) {
    anchor.position[k] = number(p[k], name + ".position");
  }
  return anchor;
}

std::size_t indexOf(const std::vector<drivers::TdoaAnchorConfig>& anchors, const std::string& id) {
  std::size_t i = 0;
  while (i < anchors.size() && anchors[i].id != id) {
    ++i;
  }
  return i;
}

}  // namespace

const ParamTable<TdoaDriverNode::Params>& TdoaDriverNode::Params::table() {
  using P = TdoaDriverNode::Params;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("address", &P::address, "", "Local address to bind.")
          .add("port", &P::port, "", "UDP port; 0 = any free port.", Range::closed(0, 65535))
          .add("frame_id", &P::frame_id, "", "Frame of the anchor positions.")
          .add("master", &P::master, "", "Id of the clock master (required).")
          .add("reference", &P::reference, "",
               "Id of the anchor differences are taken against; empty = master.")
          .add("group_window", &P::group_window, "s", "How long a blink's reports are collected.",
               Range::aboveUpTo(0.0, 1.0))
          .add("distance_variance", &P::distance_variance, "m^2", "Variance of every difference.",
               Range::above(0.0))
          .add("plausibility_margin", &P::plausibility_margin, "m",
               "Differences beyond the baseline plus this margin are discarded.",
               Range::atLeast(0.0))
          .add("min_anchors", &P::min_anchors, "",
               "Fewest anchors (reference included) per published blink.", Range::atLeast(2))
          .add("data_timeout", &P::data_timeout, "s", "Warn after this long without a datagram.",
               Range::above(0.0))
          .add("initial_backoff", &P::initial_backoff, "s",
               "First delay before re-binding after a socket failure.", Range::above(0.0))
          .add("max_backoff", &P::max_backoff, "s", "Cap of the doubling backoff.",
               Range::above(0.0));
  return t;
}

void TdoaDriverNode::Params::load(const ParamReader& nh) {
  table().load(nh, *this);
  anchors.clear();
  XmlRpc::XmlRpcValue list;
  if (nh.getRaw("anchors", list)) {
    if (list.getType() != XmlRpc::XmlRpcValue::TypeArray) {
      throw ParamError("~anchors", list.toXml(), "a list of anchors");
    }
    for (int i = 0; i < list.size(); ++i) {
      anchors.push_back(parseAnchor(list[i], "~anchors[" + std::to_string(i) + "]"));
    }
  }
}

void TdoaDriverNode::Params::validate() const {
  require(!address.empty(), "~address", address, "a local IP address");
  table().check(*this);
  require(!frame_id.empty(), "~frame_id", frame_id, "a TF frame name");
  require(anchors.size() >= 2, "~anchors", anchors.size(), "a list of at least two anchors");
  require(indexOf(anchors, master) < anchors.size(), "~master", master,
          "the id of one of ~anchors");
  require(reference.empty() || indexOf(anchors, reference) < anchors.size(), "~reference",
          reference, "empty (= master) or the id of one of ~anchors");
  require(max_backoff >= initial_backoff, "~max_backoff", max_backoff,
          "a time in seconds >= ~initial_backoff");
  differenceConfig().validate();  // anchors, variance, margin, min_anchors vs anchor count
}

drivers::TdoaDifferenceConfig TdoaDriverNode::Params::differenceConfig() const {
  drivers::TdoaDifferenceConfig c;
  c.anchors = anchors;
  c.master = indexOf(anchors, master);
  c.reference = indexOf(anchors, reference.empty() ? master : reference);
  c.distance_variance = distance_variance;
  c.plausibility_margin = plausibility_margin;
  c.min_anchors = static_cast<std::size_t>(min_anchors);
  return c;
}

}  // namespace radio_follow
