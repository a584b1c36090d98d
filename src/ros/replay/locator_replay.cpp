// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/replay/locator_replay.hpp"

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2/buffer_core.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/ros/locator/locator_inputs.hpp"
#include "radio_follow/ros/locator/odometry_lookup.hpp"
#include "radio_follow/ros/replay/bag_file.hpp"

namespace radio_follow {

BagData loadBag(const std::string& path, const std::string& truth_topic) {
  BagData data;
  rosbag::Bag bag;
  openBagForReading(bag, path);
  // The replay clock is the messages' own stamps (the drivers stamp on receipt), the
  // time base the locator node compares them with; the recorder's clock (the bag's time,
  // which may differ) only says which transforms had arrived when a measurement did, and
  // times the gaps in TF, as the node's own clock would.
  // Only the connections of these types are read (odometry, commands, ... are skipped).
  const std::vector<SensorInputKind>& kinds = sensorInputKinds();
  std::vector<std::string> type_names{"geometry_msgs/PointStamped", "tf2_msgs/TFMessage"};
  for (const SensorInputKind& kind : kinds) {
    type_names.push_back(kind.message_type);
  }
  std::string sensor_types;
  for (const SensorInputKind& kind : kinds) {
    sensor_types += (sensor_types.empty() ? "" : ", ") + kind.message_type;
  }
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TypeQuery(type_names))) {
    const double received = m.getTime().toSec();
    const auto kind = std::find_if(kinds.begin(), kinds.end(), [&](const SensorInputKind& k) {
      return k.message_type == m.getDataType();
    });
    if (kind != kinds.end()) {
      if (m.getMD5Sum() != kind->md5sum) {
        continue;  // another definition of the type: not this package's message
      }
      BagData::Entry entry;
      entry.received = received;
      entry.kind = static_cast<std::size_t>(kind - kinds.begin());
      entry.message.resize(m.size());
      ros::serialization::OStream stream(entry.message.data(),
                                         static_cast<std::uint32_t>(entry.message.size()));
      m.write(stream);
      entry.t = kind->stamp(entry.message);
      data.entries.push_back(std::move(entry));
    } else if (auto tf = m.instantiate<tf2_msgs::TFMessage>()) {
      const bool is_static = m.getTopic() == "/tf_static" || m.getTopic() == "tf_static";
      if (is_static || m.getTopic() == "/tf" || m.getTopic() == "tf") {
        for (const geometry_msgs::TransformStamped& t : tf->transforms) {
          data.tf.push_back({received, is_static, t});
        }
      }
    } else if (m.getTopic() == truth_topic || m.getTopic() == "/" + truth_topic) {
      if (auto p = m.instantiate<geometry_msgs::PointStamped>()) {
        data.truth.push_back(*p);
      }
    }
  }
  if (data.entries.empty()) {
    throw std::runtime_error("bag '" + path + "' holds no message of a sensor input (" +
                             sensor_types + ")");
  }
  std::stable_sort(data.entries.begin(), data.entries.end(),
                   [](const auto& a, const auto& b) { return a.t < b.t; });
  std::stable_sort(data.truth.begin(), data.truth.end(),
                   [](const auto& a, const auto& b) { return a.header.stamp < b.header.stamp; });
  std::stable_sort(data.tf.begin(), data.tf.end(),
                   [](const auto& a, const auto& b) { return a.received < b.received; });
  return data;
}

std::size_t BagData::count(const std::string& message_type) const {
  const std::vector<SensorInputKind>& kinds = sensorInputKinds();
  return static_cast<std::size_t>(
      std::count_if(entries.begin(), entries.end(),
                    [&](const Entry& e) { return kinds[e.kind].message_type == message_type; }));
}

namespace {

/// The truth at time t, linearly interpolated; false outside the recorded span.
bool truthAt(const std::vector<geometry_msgs::PointStamped>& truth, double t,
             Eigen::Vector2d& out) {
  const auto hi = std::lower_bound(truth.begin(), truth.end(), t,
                                   [](const geometry_msgs::PointStamped& p, double time) {
                                     return p.header.stamp.toSec() < time;
                                   });
  if (hi == truth.end() || hi == truth.begin()) {
    if (hi != truth.end() && std::abs(hi->header.stamp.toSec() - t) < 1e-9) {
      out = {hi->point.x, hi->point.y};
      return true;
    }
    return false;
  }
  const auto lo = hi - 1;
  const double t0 = lo->header.stamp.toSec();
  const double t1 = hi->header.stamp.toSec();
  const double w = t1 > t0 ? (t - t0) / (t1 - t0) : 1.0;
  out = {lo->point.x + w * (hi->point.x - lo->point.x),
         lo->point.y + w * (hi->point.y - lo->point.y)};
  return true;
}

}  // namespace

ReplayResult replay(const BagData& bag, const Layout& layout, const LocatorNode::Params& params,
                    double rate) {
  ReplayResult result;
  estimation::Locator locator(layout, params.locator);
  // The node's TF buffer as it stood when the node received each message: the bag's
  // transforms up to that message's recording time (the node's default 10 s cache).
  tf2::BufferCore tf;
  std::size_t next_tf = 0;
  double received = 0.0;
  const auto feedTf = [&](double until) {
    received = std::max(received, until);
    for (; next_tf < bag.tf.size() && bag.tf[next_tf].received <= received; ++next_tf) {
      tf.setTransform(bag.tf[next_tf].transform, "bag", bag.tf[next_tf].is_static);
    }
  };
  const bool odometry = !params.odom_frame.empty();
  std::unique_ptr<LocatorInputs> placed;
  if (odometry) {
    placed = std::make_unique<LocatorInputs>(
        locator,
        [&](const ros::Time& stamp) {
          return odometryPoseAt(tf, params.odom_frame, layout.fixed_frame, stamp,
                                params.tf_tolerance);
        },
        [&] { return received; });
  } else {
    placed = std::make_unique<LocatorInputs>(locator);
  }
  LocatorInputs& inputs = *placed;
  const double period = 1.0 / rate;
  std::size_t next = 0;
  std::size_t with_position = 0;
  result.rows.reserve(static_cast<std::size_t>(bag.duration() * rate) + 2);
  for (double now = bag.entries.front().t + period;
       next < bag.entries.size() || result.rows.empty(); now += period) {
    for (; next < bag.entries.size() && bag.entries[next].t <= now; ++next) {
      const BagData::Entry& e = bag.entries[next];
      if (odometry) {
        feedTf(e.received);
      }
      result.refused += inputs.inputs()[e.kind]->addSerialized(e.message);
    }
    ReplayRow row;
    row.t = now;
    row.estimate = locator.update(now);
    const bool has_position = hasPosition(row.estimate.status);
    with_position += has_position;
    row.has_heading = has_position || row.estimate.status == TargetStatus::kHeadingOnly;
    if (row.has_heading) {
      row.heading = std::atan2(row.estimate.position.y(), row.estimate.position.x());
    }
    if (row.has_heading && truthAt(bag.truth, row.estimate.stamp, row.truth)) {
      row.has_heading_truth = true;
      row.heading_error = wrapAngle(std::atan2(row.truth.y(), row.truth.x()) - row.heading);
      row.miss = missAtTarget(row.truth, row.heading);
      result.heading.add(toString(row.estimate.status), std::abs(row.heading_error) * 180.0 / kPi,
                         row.miss);
      if (has_position) {
        row.has_truth = true;
        row.error = (row.estimate.position.head<2>() - row.truth).norm();
        result.statistics.add(row.truth.x(), row.truth.y(), row.error);
      }
    }
    result.rows.push_back(std::move(row));
  }
  result.availability = double(with_position) / result.rows.size();
  result.placement = inputs.placement();
  result.sensors = inputs.match();
  return result;
}

std::string summaryJson(const ReplayResult& result) {
  // The position statistics' object with the heading statistics as one more member.
  std::string json = result.statistics.toJson();
  const std::size_t end = json.rfind('}');
  return json.substr(0, end) + ",\n  \"heading\": " + result.heading.toJson() + "\n}\n";
}

std::string toCsv(const ReplayResult& result) {
  std::ostringstream out;
  out.precision(9);
  out << "t,status,x,y,z,sigma_x,sigma_y,truth_x,truth_y,error,bearing_deg,heading_error_deg,"
         "miss_m\n";
  for (const ReplayRow& r : result.rows) {
    const estimation::LocatorEstimate& e = r.estimate;
    const bool position = hasPosition(e.status);
    // A bag's stamps are seconds since 1970: nine significant digits would round them
    // to tens of seconds.
    out << std::fixed << std::setprecision(6) << r.t << std::defaultfloat << std::setprecision(9)
        << "," << toString(e.status) << ",";
    if (position) {
      out << e.position.x() << "," << e.position.y() << "," << e.position.z() << ","
          << std::sqrt(std::max(0.0, e.covariance(0, 0))) << ","
          << std::sqrt(std::max(0.0, e.covariance(1, 1))) << ",";
    } else {
      out << ",,,,,";
    }
    if (r.has_heading_truth) {
      out << r.truth.x() << "," << r.truth.y() << ",";
    } else {
      out << ",,";
    }
    if (r.has_truth) {
      out << r.error;
    }
    out << ",";
    if (r.has_heading) {
      out << r.heading * 180.0 / kPi;
    }
    out << ",";
    if (r.has_heading_truth) {
      out << r.heading_error * 180.0 / kPi << "," << r.miss;
    } else {
      out << ",";
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace radio_follow
