// SPDX-License-Identifier: BSD-3-Clause
// Collects the status names the demo's nodes publish on /diagnostics and checks that the
// analyzers of config/diagnostics_aggregator.yaml match every one (GenericAnalyzer rules:
// name, startswith, contains, as diagnostic_aggregator applies them), and that no
// status shows a numeric controller state or a "none" hardware id.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <yaml-cpp/yaml.h>

#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace {

struct Analyzer {
  std::string path;
  std::vector<std::string> names, startswith, contains;

  bool matches(const std::string& status) const {
    for (const auto& n : names) {
      if (status == n)
        return true;
    }
    for (const auto& s : startswith) {
      if (status.rfind(s, 0) == 0)
        return true;
    }
    for (const auto& c : contains) {
      if (status.find(c) != std::string::npos)
        return true;
    }
    return false;
  }
};

std::vector<std::string> strings(const YAML::Node& node) {
  std::vector<std::string> out;
  if (node && node.IsSequence()) {
    for (const auto& item : node)
      out.push_back(item.as<std::string>());
  } else if (node && node.IsScalar()) {
    out.push_back(node.as<std::string>());
  }
  return out;
}

void collect(const YAML::Node& analyzers, const std::string& prefix, std::vector<Analyzer>& out) {
  for (const auto& entry : analyzers) {
    const YAML::Node a = entry.second;
    const std::string type = a["type"].as<std::string>();
    const std::string path = prefix + "/" + a["path"].as<std::string>();
    if (type == "diagnostic_aggregator/AnalyzerGroup") {
      collect(a["analyzers"], path, out);
    } else {
      ASSERT_EQ(type, "diagnostic_aggregator/GenericAnalyzer") << path;
      out.push_back({path, strings(a["name"]), strings(a["startswith"]), strings(a["contains"])});
    }
  }
}

TEST(DiagnosticsAggregator, EveryPublishedStatusIsMatchedByAnAnalyzer) {
  ros::NodeHandle pnh("~");
  std::string config;
  ASSERT_TRUE(pnh.getParam("config", config));
  std::vector<Analyzer> analyzers;
  collect(YAML::LoadFile(config)["analyzers"], "", analyzers);
  ASSERT_EQ(analyzers.size(), 5u);  // UWB, AoA, TDoA, locator, controllers

  std::mutex mutex;
  std::map<std::string, diagnostic_msgs::DiagnosticStatus> seen;
  ros::NodeHandle nh;
  ros::Subscriber sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 100, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
        const std::lock_guard<std::mutex> lock(mutex);
        for (const auto& s : msg->status)
          seen[s.name] = s;
      });
  // 3 UWB drivers (a status, ranges; tag_location only once a module reports a position of
  // its own, which the simulated ones do not), 4 AoA drivers (a status, bearing), the
  // locator (a status and two outputs), the controller (a status and cmd_vel): 19 names.
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(60.0);
  while (ros::WallTime::now() < deadline) {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      if (seen.size() >= 22)
        break;
    }
    ros::WallDuration(0.2).sleep();
  }
  ros::WallDuration(2.0).sleep();  // and whatever else comes
  const std::lock_guard<std::mutex> lock(mutex);
  EXPECT_GE(seen.size(), 19u);
  for (const auto& [name, status] : seen) {
    // An output with nothing to say is no error (OutputDiagnostic registers it late).
    EXPECT_EQ(name.find("tag_location"), std::string::npos) << name << " reported unused";
  }
  std::set<std::string> used;
  std::vector<std::string> names;
  for (const auto& [name, status] : seen)
    names.push_back(name);
  names.push_back("tdoa_driver: TDoA anchors");  // not in the demo
  names.push_back("tdoa_driver: TDoA anchors output /tdoa/measurements topic status");
  for (const auto& name : names) {
    int matched = 0;
    for (const auto& a : analyzers) {
      if (a.matches(name)) {
        ++matched;
        used.insert(a.path);
      }
    }
    EXPECT_EQ(matched, 1) << "'" << name << "' matched by " << matched << " analyzers";
  }
  EXPECT_EQ(used.size(), analyzers.size()) << "an analyzer matches nothing";

  for (const auto& [name, status] : seen) {
    EXPECT_FALSE(status.hardware_id.empty() || status.hardware_id == "none") << name;
    for (const auto& kv : status.values) {
      if (kv.key == "state") {
        EXPECT_TRUE(kv.value.find_first_of("0123456789") == std::string::npos)
            << name << ": state " << kv.value;
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "diagnostics_aggregator_rostest");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
