// SPDX-License-Identifier: BSD-3-Clause
// The parameter tables (common/param_table.hpp): the mechanism itself, and that every
// entry of the node structs' tables is in its commented config/*.yaml with the table's
// default and in its doc/nodes/*.md parameter table with the same default. Adding a
// parameter is one table entry; this test then names the YAML and doc lines it needs.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../../support/param_coverage.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_table.hpp"
#include "radio_follow/common/yaml_params.hpp"
#include "radio_follow/control/command_pipeline.hpp"
#include "radio_follow/control/homing_controller.hpp"
#include "radio_follow/control/path_follower.hpp"
#include "radio_follow/control/velocity_law.hpp"
#include "radio_follow/drivers/dwm1001_params.hpp"
#include "radio_follow/drivers/ublox_aoa_params.hpp"
#include "radio_follow/estimation/locator.hpp"

namespace radio_follow {
namespace {

struct Example {
  double distance = 1.5;
  int count = 3;
  bool flag = false;
  std::string name = "a";
  double angle = 0.5;  // rad
  enum class Mode { kOne, kTwo } mode = Mode::kOne;
  struct Inner {
    double gain = 2.0;
  } inner;
};

ParamTable<Example::Inner> innerTable() {
  return ParamTable<Example::Inner>().add("gain", &Example::Inner::gain, "", "A gain.",
                                          Range::atLeast(0.0));
}

ParamTable<Example> exampleTable() {
  return ParamTable<Example>()
      .add("distance", &Example::distance, "m", "A distance.", Range::closed(0.5, 10.0))
      .add("count", &Example::count, "", "A count.", Range::atLeast(1))
      .add("flag", &Example::flag, "", "A flag.")
      .add("name", &Example::name, "", "A name.")
      .addScaled("angle_deg", &Example::angle, M_PI / 180.0, "deg", "An angle.",
                 Range::open(0.0, 90.0))
      .addChoice("mode", &Example::mode,
                 std::vector<std::pair<std::string, Example::Mode>>{{"one", Example::Mode::kOne},
                                                                    {"two", Example::Mode::kTwo}},
                 "A mode.")
      .include(innerTable(), &Example::inner, "inner/");
}

TEST(ParamTable, LoadsEveryKindAndKeepsAbsentKeys) {
  const YamlParams source(
      YAML::Load("{distance: 2, flag: true, angle_deg: 45.0, mode: two, inner: {gain: 3.0}}"));
  Example e;
  exampleTable().load(source, e);
  EXPECT_DOUBLE_EQ(e.distance, 2.0);  // an int where a double is expected
  EXPECT_EQ(e.count, 3);              // absent: kept
  EXPECT_TRUE(e.flag);
  EXPECT_NEAR(e.angle, M_PI / 4.0, 1e-12);
  EXPECT_EQ(e.mode, Example::Mode::kTwo);
  EXPECT_DOUBLE_EQ(e.inner.gain, 3.0);
  source.requireAllKnown();  // every key was an entry
}

TEST(ParamTable, RefusesOutOfRangeWrongTypeAndUnknownChoiceNamingTheParameter) {
  const auto fails = [](const std::string& yaml, const std::string& name) {
    Example e;
    try {
      exampleTable().load(YamlParams(YAML::Load(yaml)), e);
      exampleTable().check(e);
      ADD_FAILURE() << yaml << " was accepted";
    } catch (const ParamError& error) {
      EXPECT_EQ(error.name(), name) << error.what();
    }
  };
  fails("{distance: 0.1}", "~distance");
  fails("{distance: .nan}", "~distance");
  fails("{count: 0}", "~count");
  fails("{count: 1.5}", "~count");
  fails("{angle_deg: 90.0}", "~angle_deg");
  fails("{mode: three}", "~mode");
  fails("{inner: {gain: -1.0}}", "~inner/gain");
}

TEST(ParamTable, ReportsValuesInTheParametersUnits) {
  const ParamTable<Example> t = exampleTable();
  const Example e;
  EXPECT_EQ(paramValueText(t.find("distance")->get(e)), "1.5");
  EXPECT_NEAR(std::get<double>(t.find("angle_deg")->get(e)), 0.5 * 180.0 / M_PI, 1e-9);
  EXPECT_EQ(paramValueText(t.find("mode")->get(e)), "'one'");
  EXPECT_EQ(t.find("inner/gain")->unit, "");
  EXPECT_EQ(Range::closed(0.5, 10.0).text(), "in [0.5, 10]");
  EXPECT_EQ(Range::above(0.0).text(), "> 0");
}

// --- The node structs' tables against config/*.yaml and doc/nodes/*.md -------------------
// (test/support/param_coverage.hpp; the ROS nodes' own tables: test/unit/ros/)

TEST(ParamTables, ControllerCommonIsInItsYamlAndDoc) {
  // target_anchor_id and calibrate_ranges follow the layout unless set: the YAML leaves
  // them out on purpose (its comments say so).
  expectCovered(control::CommandPipelineParams::table(), {"controller_common.yaml"},
                "nodes/velocity_controller.md", {"target_anchor_id"});
}

TEST(ParamTables, VelocityLawIsInItsYamlAndDoc) {
  expectCovered(control::VelocityLawParams::table(), {"velocity_controller.yaml"},
                "nodes/velocity_controller.md");
}

TEST(ParamTables, PathFollowerIsInItsYamlAndDoc) {
  expectCovered(control::PathFollowParams::table(), {"path_follower.yaml"},
                "nodes/path_follower.md");
}

TEST(ParamTables, HomingControllerIsInItsYamlAndDoc) {
  expectCovered(control::HomingControllerParams::table(), {"homing_controller.yaml"},
                "nodes/homing_controller.md");
}

TEST(ParamTables, LocatorIsInItsYamlAndDoc) {
  expectCovered(estimation::LocatorConfig::table(), {"locator.yaml"}, "nodes/locator.md");
}

// --- The live-tuning .cfg files against the tables ----------------------------------------
// dynamic_reconfigure's .cfg files are Python and give every field a default. The server
// starts with the node's loaded values, so that default is never used, but it is a second
// copy of the table's: each literal `.add("name", type, 0, "description", default` must
// name a table entry (`linear_pid_kp` for `linear_pid/kp`) and carry the table's default.
// (The .cfg files give no bounds: the tables' validate() judges a live change.)

struct CfgField {
  std::string name;
  std::string value;
};

std::vector<CfgField> cfgFields(const std::string& file) {
  const std::string text = readFile(std::string(RF_CONFIG_DIR) + "/../cfg/" + file);
  EXPECT_FALSE(text.empty()) << file;
  static const std::regex add(
      R"re(\.add\("([a-z0-9_]+)",\s*(?:double_t|int_t|bool_t|str_t),\s*0,\s*"[^"]*",\s*("[^"]*"|[-+0-9.eE]+|True|False))re");
  std::vector<CfgField> fields;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), add); it != std::sregex_iterator();
       ++it) {
    std::string value = (*it)[2];
    if (value == "True" || value == "False") {
      value = value == "True" ? "true" : "false";
    }
    fields.push_back({(*it)[1], value});
  }
  return fields;
}

template <typename S>
void expectCfgDefaultsAreTheTables(const ParamTable<S>& table, const std::string& file) {
  S defaults;  // (S{} trips a false maybe-uninitialized warning in GCC 12 for derived aggregates)
  const std::vector<CfgField> fields = cfgFields(file);
  EXPECT_GE(fields.size(), 5u) << file << ": the pattern found too few fields";
  for (const CfgField& field : fields) {
    if (field.name == "refused") {
      continue;  // not a parameter: the server's answer to the last change
    }
    bool found = false;
    for (const auto& e : table.entries()) {
      std::string flat = e.name;
      std::replace(flat.begin(), flat.end(), '/', '_');
      if (flat != field.name) {
        continue;
      }
      found = true;
      const ParamValue value = e.get(defaults);
      EXPECT_TRUE(sameValue(value, field.value))
          << "cfg/" << file << ": " << field.name << " defaults to " << field.value
          << ", the table's default is " << paramValueText(value);
    }
    EXPECT_TRUE(found) << "cfg/" << file << ": " << field.name << " is no parameter of the table";
  }
}

TEST(ParamTables, SerialDriversAreInTheirYamlAndDoc) {
  // The device path differs per device (the launch file gives it); a board's frame too.
  expectCovered(drivers::Dwm1001Params::table(), {"dwm1001_driver.yaml"}, "nodes/dwm1001_driver.md",
                {"port"});
  expectCovered(drivers::UbloxAoaParams::table(), {"ublox_aoa_driver.yaml"},
                "nodes/ublox_aoa_driver.md", {"port", "frame_id"});
}

TEST(ParamTables, LiveTuningDefaultsAreTheTables) {
  expectCfgDefaultsAreTheTables(control::CommandPipelineParams::table(), "ControllerTuning.cfg");
  expectCfgDefaultsAreTheTables(control::VelocityLawParams::table(), "FollowLawTuning.cfg");
  expectCfgDefaultsAreTheTables(estimation::LocatorConfig::table(), "LocatorTuning.cfg");
}

// Issue 33: a sweep over the robust losses under the particle estimator was identical to
// six digits. Such a setting is named at start; the shipped files name none.
TEST(ParamTables, LocatorNamesSettingsItsEstimatorIgnores) {
  for (const char* file : {"locator.yaml", "locator_standing.yaml"}) {
    estimation::LocatorConfig shipped;
    shipped.load(YamlParams(YAML::LoadFile(std::string(RF_CONFIG_DIR) + "/" + file)));
    EXPECT_TRUE(shipped.ignoredSettings().empty()) << file << ": " << shipped.ignoredSettings()[0];
  }
  estimation::LocatorConfig particle;
  particle.load(YamlParams(YAML::Load("{range_loss: huber, bearing_loss_scale: 3.0}")));
  const std::vector<std::string> lines = particle.ignoredSettings();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("~range_loss = 'huber' has no effect with estimator particle"),
            std::string::npos)
      << lines[0];
  EXPECT_NE(lines[1].find("~bearing_loss_scale"), std::string::npos) << lines[1];

  estimation::LocatorConfig solver;
  solver.load(YamlParams(YAML::Load("{estimator: solver, range_loss: huber, particles: 900}")));
  ASSERT_EQ(solver.ignoredSettings().size(), 1u);
  EXPECT_NE(
      solver.ignoredSettings()[0].find("~particles = 900 has no effect with estimator solver"),
      std::string::npos)
      << solver.ignoredSettings()[0];
}

}  // namespace
}  // namespace radio_follow
