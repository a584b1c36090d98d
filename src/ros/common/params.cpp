// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/common/params.hpp"

#include <ros/names.h>

#include <cmath>
#include <sstream>
#include <utility>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"

namespace radio_follow {
namespace {

using XmlRpc::XmlRpcValue;

std::string render(const XmlRpcValue& value) {
  // XmlRpcValue::toXml is noisy; a compact rendering of what the user wrote is enough.
  std::ostringstream out;
  switch (value.getType()) {
    case XmlRpcValue::TypeString:
      out << "'" << static_cast<std::string>(const_cast<XmlRpcValue&>(value)) << "'";
      break;
    case XmlRpcValue::TypeArray: {
      out << "[";
      XmlRpcValue& v = const_cast<XmlRpcValue&>(value);
      for (int i = 0; i < v.size(); ++i) {
        out << (i > 0 ? ", " : "") << render(v[i]);
      }
      out << "]";
      break;
    }
    case XmlRpcValue::TypeStruct:
      out << "{...}";
      break;
    default:
      const_cast<XmlRpcValue&>(value).write(out);
  }
  return out.str();
}

[[noreturn]] void wrongType(const std::string& name, const XmlRpcValue& value,
                            const std::string& expected) {
  throw ParamError(name, render(value), expected);
}

bool isNumber(const XmlRpcValue& v) {
  return v.getType() == XmlRpcValue::TypeDouble || v.getType() == XmlRpcValue::TypeInt;
}

double toDouble(XmlRpcValue& v) {
  return v.getType() == XmlRpcValue::TypeInt ? static_cast<double>(static_cast<int>(v))
                                             : static_cast<double>(v);
}

void convert(const std::string& name, XmlRpcValue& v, bool& out) {
  if (v.getType() != XmlRpcValue::TypeBoolean) {
    wrongType(name, v, "true or false");
  }
  out = static_cast<bool>(v);
}

void convert(const std::string& name, XmlRpcValue& v, int& out) {
  if (v.getType() != XmlRpcValue::TypeInt) {
    wrongType(name, v, "a whole number");
  }
  out = static_cast<int>(v);
}

void convert(const std::string& name, XmlRpcValue& v, double& out) {
  if (!isNumber(v) || !std::isfinite(toDouble(v))) {
    wrongType(name, v, "a finite number");
  }
  out = toDouble(v);
}

void convert(const std::string& name, XmlRpcValue& v, std::string& out) {
  if (v.getType() != XmlRpcValue::TypeString) {
    wrongType(name, v, "a string (quote values such as IDs that look like numbers)");
  }
  out = static_cast<std::string>(v);
}

void convert(const std::string& name, XmlRpcValue& v, std::vector<std::string>& out) {
  if (v.getType() != XmlRpcValue::TypeArray) {
    wrongType(name, v, "a list of strings, e.g. [a, b]");
  }
  std::vector<std::string> list;
  for (int i = 0; i < v.size(); ++i) {
    if (v[i].getType() != XmlRpcValue::TypeString) {
      wrongType(name, v, "a list of strings, e.g. [a, b]");
    }
    list.push_back(static_cast<std::string>(v[i]));
  }
  out = list;
}

void convert(const std::string& name, XmlRpcValue& v, std::vector<double>& out) {
  if (v.getType() != XmlRpcValue::TypeArray) {
    wrongType(name, v, "a list of finite numbers");
  }
  std::vector<double> list;
  for (int i = 0; i < v.size(); ++i) {
    if (!isNumber(v[i]) || !std::isfinite(toDouble(v[i]))) {
      wrongType(name, v, "a list of finite numbers");
    }
    list.push_back(toDouble(v[i]));
  }
  out = list;
}

}  // namespace

ParamReader::ParamReader(const ros::NodeHandle& private_nh, std::string shown_as)
    : nh_(private_nh), shown_as_(std::move(shown_as)) {}

template <typename T>
bool ParamReader::readAs(const std::string& name, T& out) const {
  known_.insert(name);
  XmlRpcValue value;
  if (!nh_.getParam(name, value)) {
    return false;
  }
  convert(shown_as_ + name, value, out);
  return true;
}

// The six types TypedParamSource reads (its overrides are inline in every user).
template bool ParamReader::readAs(const std::string&, bool&) const;
template bool ParamReader::readAs(const std::string&, int&) const;
template bool ParamReader::readAs(const std::string&, double&) const;
template bool ParamReader::readAs(const std::string&, std::string&) const;
template bool ParamReader::readAs(const std::string&, std::vector<std::string>&) const;
template bool ParamReader::readAs(const std::string&, std::vector<double>&) const;

bool ParamReader::getRaw(const std::string& name, XmlRpcValue& out) const {
  known_.insert(name);
  return nh_.getParam(name, out);
}

void ParamReader::own(const std::string& ns) const {
  owned_.push_back(ns);
}

void ParamReader::allow(const std::string& name) const {
  known_.insert(name);
}

std::string ParamReader::relative(const std::string& resolved) const {
  const std::string prefix = nh_.getNamespace() == "/" ? "/" : nh_.getNamespace() + "/";
  return resolved.compare(0, prefix.size(), prefix) == 0 ? resolved.substr(prefix.size()) : "";
}

void ParamReader::requireAllKnown() const {
  std::vector<std::string> names;
  if (!ros::param::getParamNames(names)) {
    return;  // no master answer: the reads above would have failed loudly already
  }
  std::vector<PresentKey> present;
  for (const std::string& resolved : names) {
    const std::string name = relative(resolved);
    if (name.empty()) {
      continue;
    }
    XmlRpcValue value;
    nh_.getParam(name, value);
    present.push_back({name, render(value)});
  }
  requireKnownKeys(present, known_, owned_, shown_as_);
}

void requireMembers(const XmlRpcValue& item, const std::set<std::string>& allowed,
                    const std::string& path) {
  if (item.getType() != XmlRpcValue::TypeStruct) {
    return;  // the caller reports a non-mapping with its own expectation
  }
  std::vector<PresentKey> present;
  for (const auto& member : const_cast<XmlRpcValue&>(item)) {
    present.push_back({member.first, render(member.second)});
  }
  requireKnownKeys(present, allowed, {}, path + ".");
}

void requireGraphName(const std::string& param, const std::string& name) {
  std::string error = "empty";
  if (name.empty() || !ros::names::validate(name, error)) {
    throw ParamError(param, paramValueString(name), "a valid ROS name (" + error + ")");
  }
}

}  // namespace radio_follow
