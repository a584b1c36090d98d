// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/replay/calibration_bag.hpp"

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <algorithm>
#include <stdexcept>

#include "radio_follow/AoaBearing.h"
#include "radio_follow/UwbRanges.h"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/ros/replay/bag_file.hpp"

namespace radio_follow {
namespace {

using Measurement = estimation::CalibrationMeasurement;

const char* const kRangesType = "radio_follow/UwbRanges";
const char* const kBearingType = "radio_follow/AoaBearing";
const std::vector<std::string> kTruthTypes = {"geometry_msgs/PointStamped",
                                              "geometry_msgs/PoseStamped", "nav_msgs/Odometry"};

std::string bare(const std::string& topic) {
  return !topic.empty() && topic[0] == '/' ? topic.substr(1) : topic;
}

/// The truth sample of a message of any of kTruthTypes, with its header.
bool truthOf(const rosbag::MessageInstance& m, std_msgs::Header& header,
             Eigen::Vector3d& position) {
  if (auto p = m.instantiate<geometry_msgs::PointStamped>()) {
    header = p->header;
    position = {p->point.x, p->point.y, p->point.z};
  } else if (auto s = m.instantiate<geometry_msgs::PoseStamped>()) {
    header = s->header;
    position = {s->pose.position.x, s->pose.position.y, s->pose.position.z};
  } else if (auto o = m.instantiate<nav_msgs::Odometry>()) {
    header = o->header;
    position = {o->pose.pose.position.x, o->pose.pose.position.y, o->pose.pose.position.z};
  } else {
    return false;
  }
  return true;
}

}  // namespace

std::string topicsOfType(const CalibrationBag& bag, const std::string& type) {
  std::string list;
  for (const auto& kv : bag.bag_topics) {
    if (kv.second == type) {
      list += (list.empty() ? "" : ", ") + kv.first;
    }
  }
  return list.empty() ? "none" : list;
}

CalibrationBag loadCalibrationBag(const std::string& path, const Layout& layout,
                                  const CalibrationTopics& topics) {
  CalibrationBag data;
  rosbag::Bag bag;
  openBagForReading(bag, path);
  rosbag::View everything(bag);
  for (const rosbag::ConnectionInfo* c : everything.getConnections()) {
    data.bag_topics[c->topic] = c->datatype;
  }
  // What each requested topic is: its expected type, and for sensors their kind.
  std::map<std::string, std::string> wanted;
  std::map<std::string, Measurement::Kind> kind;
  std::map<std::string, std::string> given;  // bare name -> as the caller wrote it
  for (const std::string& t : topics.uwb) {
    wanted[bare(t)] = kRangesType;
    kind[bare(t)] = Measurement::Kind::kRange;
    given[bare(t)] = t;
    data.messages[t] = 0;
  }
  for (const std::string& t : topics.aoa) {
    wanted[bare(t)] = kBearingType;
    kind[bare(t)] = Measurement::Kind::kBearing;
    given[bare(t)] = t;
    data.messages[t] = 0;
  }
  for (const auto& kv : data.bag_topics) {
    const auto w = wanted.find(bare(kv.first));
    if (w != wanted.end() && w->second != kv.second) {
      throw std::runtime_error("bag '" + path + "': topic " + kv.first + " is " + kv.second +
                               ", expected " + w->second);
    }
  }
  const std::string truth = bare(topics.truth);
  if (!truth.empty()) {
    const auto found = data.bag_topics.find("/" + truth) != data.bag_topics.end()
                           ? data.bag_topics.find("/" + truth)
                           : data.bag_topics.find(truth);
    std::string usable;
    for (const std::string& type : kTruthTypes) {
      const std::string list = topicsOfType(data, type);
      usable += list == "none" ? "" : (usable.empty() ? "" : ", ") + list;
    }
    if (found == data.bag_topics.end()) {
      throw std::runtime_error("bag '" + path + "' has no topic " + topics.truth +
                               " (ground-truth topics of a usable type in it: " +
                               (usable.empty() ? "none" : usable) + ")");
    }
    if (std::find(kTruthTypes.begin(), kTruthTypes.end(), found->second) == kTruthTypes.end()) {
      throw std::runtime_error("bag '" + path + "': topic " + found->first + " is " +
                               found->second +
                               ", expected geometry_msgs/PointStamped, PoseStamped or "
                               "nav_msgs/Odometry");
    }
  }

  const double start = everything.getBeginTime().toSec();
  data.duration = everything.getEndTime().toSec() - start;
  // Only the requested topics are read (TF, odometry, diagnostics, ... are skipped).
  std::vector<std::string> read;
  for (const auto& kv : data.bag_topics) {
    if (kind.count(bare(kv.first)) > 0 || (!truth.empty() && bare(kv.first) == truth)) {
      read.push_back(kv.first);
    }
  }
  rosbag::View view(bag, rosbag::TopicQuery(read));
  for (const rosbag::MessageInstance& m : view) {
    const std::string topic = bare(m.getTopic());
    const double since_start = m.getTime().toSec() - start;
    if (!truth.empty() && topic == truth) {
      std_msgs::Header header;
      Eigen::Vector3d position;
      truthOf(m, header, position);
      if (!header.frame_id.empty() && bare(header.frame_id) != bare(layout.fixed_frame)) {
        // A pose in another frame would be compared as if in the robot's: every fit wrong.
        throw std::runtime_error("bag '" + path + "': " + m.getTopic() + " is in frame '" +
                                 header.frame_id + "', the layout's fixed frame is '" +
                                 layout.fixed_frame +
                                 "': record the tag's position in the robot's fixed frame");
      }
      data.truth.push_back({header.stamp.toSec(), position});
      continue;
    }
    const auto k = kind.find(topic);
    if (k == kind.end()) {
      continue;
    }
    ++data.messages[given[topic]];
    if (k->second == Measurement::Kind::kRange) {
      const auto r = m.instantiate<UwbRanges>();
      // As the locator: the module by ID, by frame when the driver had no ID.
      const std::string module = r->tag_id.empty() ? r->header.frame_id : r->tag_id;
      for (const auto& range : r->ranges) {
        if (normalizeId(range.anchor_id) != layout.target_anchor_id) {
          ++data.other_anchors;
          continue;
        }
        data.measurements.push_back(
            {Measurement::Kind::kRange, module, r->header.stamp.toSec(), since_start, range.range});
      }
    } else {
      const auto b = m.instantiate<AoaBearing>();
      if (!layout.target_tag_id.empty() && normalizeId(b->tag_id) != layout.target_tag_id) {
        ++data.other_tags;
        continue;
      }
      data.measurements.push_back({Measurement::Kind::kBearing, b->header.frame_id,
                                   b->header.stamp.toSec(), since_start, b->azimuth, b->elevation});
    }
  }
  return data;
}

}  // namespace radio_follow
