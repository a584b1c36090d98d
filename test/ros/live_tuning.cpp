// SPDX-License-Identifier: BSD-3-Clause
// Live tuning of the running locator and velocity_controller through their
// dynamic_reconfigure services: each server starts with the loaded parameters, a valid
// change is applied and written back to the parameter server, an invalid one is refused
// and the old value stays.
#include <dynamic_reconfigure/Reconfigure.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <ros/topic.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "radio_follow/ControllerTuningConfig.h"
#include "radio_follow/FollowLawTuningConfig.h"
#include "radio_follow/LocatorTuningConfig.h"
#include "radio_follow/control/command_pipeline.hpp"
#include "radio_follow/control/velocity_law.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/ros/common/reconfigure_table.hpp"

namespace {

constexpr char kService[] = "locator/set_parameters";
constexpr char kControllerService[] = "velocity_controller/set_parameters";
constexpr char kLawService[] = "velocity_controller/law/set_parameters";

dynamic_reconfigure::Config call(const dynamic_reconfigure::Config& request,
                                 const std::string& service = kService) {
  dynamic_reconfigure::Reconfigure srv;
  srv.request.config = request;
  EXPECT_TRUE(ros::service::call(service, srv)) << service << " failed";
  return srv.response.config;
}

dynamic_reconfigure::Config withDouble(const std::string& name, double value) {
  dynamic_reconfigure::Config c;
  dynamic_reconfigure::DoubleParameter p;
  p.name = name;
  p.value = value;
  c.doubles.push_back(p);
  return c;
}

dynamic_reconfigure::Config withString(const std::string& name, const std::string& value) {
  dynamic_reconfigure::Config c;
  dynamic_reconfigure::StrParameter p;
  p.name = name;
  p.value = value;
  c.strs.push_back(p);
  return c;
}

double doubleOf(const dynamic_reconfigure::Config& c, const std::string& name) {
  for (const auto& p : c.doubles) {
    if (p.name == name) {
      return p.value;
    }
  }
  ADD_FAILURE() << name << " missing from the response";
  return -1.0;
}

std::string stringOf(const dynamic_reconfigure::Config& c, const std::string& name) {
  for (const auto& p : c.strs) {
    if (p.name == name) {
      return p.value;
    }
  }
  ADD_FAILURE() << name << " missing from the response";
  return "";
}

double param(const std::string& name, const std::string& node = "locator") {
  double value = -1.0;
  EXPECT_TRUE(ros::param::get(node + "/" + name, value)) << name;
  return value;
}

class LiveTuning : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* service : {kService, kControllerService, kLawService}) {
      ASSERT_TRUE(ros::service::waitForService(service, ros::Duration(30.0)))
          << "no " << service << " within 30 s";
    }
  }
};

TEST_F(LiveTuning, LocatorStartsWithTheLoadedParameters) {
  const auto current = call(dynamic_reconfigure::Config());
  EXPECT_DOUBLE_EQ(doubleOf(current, "range_sigma"), 0.05);  // launch file, not the .cfg
  EXPECT_EQ(stringOf(current, "range_loss"), "huber");
  EXPECT_DOUBLE_EQ(doubleOf(current, "gate_probability"), 0.999);  // core default
}

TEST_F(LiveTuning, LocatorAppliesAValidChange) {
  const auto after = call(withDouble("azimuth_sigma_deg", 7.5));
  EXPECT_DOUBLE_EQ(doubleOf(after, "azimuth_sigma_deg"), 7.5);
  EXPECT_DOUBLE_EQ(param("azimuth_sigma_deg"), 7.5);
  const auto model = call(withString("motion_model", "constant_velocity"));
  EXPECT_EQ(stringOf(model, "motion_model"), "constant_velocity");
}

TEST_F(LiveTuning, LocatorRefusesAnInvalidChangeAndKeepsTheOldValue) {
  // In the .cfg's range [0, 1] but not a valid gate (validate: 0 or in (0.5, 1)).
  const auto gate = call(withDouble("gate_probability", 0.3));
  EXPECT_DOUBLE_EQ(doubleOf(gate, "gate_probability"), 0.999);
  EXPECT_DOUBLE_EQ(param("gate_probability"), 0.999);
  const auto sigma = call(withDouble("range_sigma", 0.0));
  EXPECT_DOUBLE_EQ(doubleOf(sigma, "range_sigma"), 0.05);
  EXPECT_DOUBLE_EQ(param("range_sigma"), 0.05);
  const auto loss = call(withString("range_loss", "quadratic"));
  EXPECT_EQ(stringOf(loss, "range_loss"), "huber");
}

// The answer says why: `refused` names the parameter, the value and what is expected
// (what the node logs), and an accepted change clears it. `dynparam get` shows it.
TEST_F(LiveTuning, ARefusalIsInTheAnswerAndAnAcceptedChangeClearsIt) {
  const auto refused = call(withDouble("gate_probability", 0.3));
  const std::string why = stringOf(refused, "refused");
  EXPECT_NE(why.find("~gate_probability"), std::string::npos) << why;
  EXPECT_NE(why.find("0.3"), std::string::npos) << why;
  EXPECT_NE(why.find("expected"), std::string::npos) << why;
  // What `dynparam get` reads: the server's latched parameter_updates.
  const auto published = ros::topic::waitForMessage<dynamic_reconfigure::Config>(
      "locator/parameter_updates", ros::Duration(10.0));
  ASSERT_TRUE(published);
  EXPECT_EQ(stringOf(*published, "refused"), why);
  EXPECT_EQ(stringOf(call(withDouble("gate_probability", 0.99)), "refused"), "");
  EXPECT_DOUBLE_EQ(param("gate_probability"), 0.99);
  call(withDouble("gate_probability", 0.999));
  const auto law = call(withDouble("max_follow_sigma", -1.0), kLawService);
  EXPECT_NE(stringOf(law, "refused").find("~max_follow_sigma"), std::string::npos)
      << stringOf(law, "refused");
  EXPECT_DOUBLE_EQ(doubleOf(law, "max_follow_sigma"), 0.5);
}

TEST_F(LiveTuning, ControllerSafeDistanceKeepsItsValidation) {
  const auto start = call(dynamic_reconfigure::Config(), kControllerService);
  EXPECT_DOUBLE_EQ(doubleOf(start, "safe_distance"), 1.1);  // launch file, not the .cfg
  const auto wider = call(withDouble("safe_distance", 1.6), kControllerService);
  EXPECT_DOUBLE_EQ(doubleOf(wider, "safe_distance"), 1.6);
  EXPECT_DOUBLE_EQ(param("safe_distance", "velocity_controller"), 1.6);
  const auto negative = call(withDouble("safe_distance", -0.5), kControllerService);
  EXPECT_DOUBLE_EQ(doubleOf(negative, "safe_distance"), 1.6);
  EXPECT_DOUBLE_EQ(param("safe_distance", "velocity_controller"), 1.6);
  const auto stopped = call(withDouble("max_linear", 0.0), kControllerService);
  EXPECT_GT(doubleOf(stopped, "max_linear"), 0.0);
}

TEST_F(LiveTuning, ControllerLawGainsAndDistancesAreTunable) {
  const auto start = call(dynamic_reconfigure::Config(), kLawService);
  EXPECT_DOUBLE_EQ(doubleOf(start, "follow_distance"), 2.2);  // launch file, not the .cfg
  EXPECT_DOUBLE_EQ(doubleOf(start, "linear_pid_kp"), 1.0);    // the node's default
  const auto closer = call(withDouble("follow_distance", 1.8), kLawService);
  EXPECT_DOUBLE_EQ(doubleOf(closer, "follow_distance"), 1.8);
  const auto gain = call(withDouble("linear_pid_kp", 1.2), kLawService);
  EXPECT_DOUBLE_EQ(doubleOf(gain, "linear_pid_kp"), 1.2);
  // The parameter server holds what runs, under the node's own names (not only ~law/...).
  EXPECT_DOUBLE_EQ(param("follow_distance", "velocity_controller"), 1.8);
  EXPECT_DOUBLE_EQ(param("linear_pid/kp", "velocity_controller"), 1.2);
  // VelocityLawParams::validate: a distance > 0, a factor in [0, 1].
  const auto negative = call(withDouble("follow_distance", -1.0), kLawService);
  EXPECT_DOUBLE_EQ(doubleOf(negative, "follow_distance"), 1.8);
  EXPECT_DOUBLE_EQ(param("follow_distance", "velocity_controller"), 1.8);  // refused: kept
  const auto factor = call(withDouble("feed_forward", 1.5), kLawService);
  EXPECT_DOUBLE_EQ(doubleOf(factor, "feed_forward"), 1.0);
}

// The same physical bounds as at start (issue 12): in live tuning too, no stop distance
// the follow law cannot clear, no freshness timeout of minutes, no stop distance of 0.
// Runs after the two tests above: safe_distance 1.6 m, follow_distance 1.8 m.
TEST_F(LiveTuning, SafetyBoundsHoldInLiveTuning) {
  const auto tiny = call(withDouble("safe_distance", 0.1), kControllerService);
  EXPECT_DOUBLE_EQ(doubleOf(tiny, "safe_distance"), 1.6);
  // 1.7 m > follow_distance 1.8 - closing_distance 0.2: the law would still drive there.
  const auto beyond = call(withDouble("safe_distance", 1.7), kControllerService);
  EXPECT_DOUBLE_EQ(doubleOf(beyond, "safe_distance"), 1.6);
  EXPECT_DOUBLE_EQ(param("safe_distance", "velocity_controller"), 1.6);
  const auto closer = call(withDouble("follow_distance", 1.7), kLawService);
  EXPECT_DOUBLE_EQ(doubleOf(closer, "follow_distance"), 1.8);
  const auto slow = call(withDouble("estimate_timeout", 9.0), kControllerService);
  EXPECT_DOUBLE_EQ(doubleOf(slow, "estimate_timeout"), 0.5);
}

// A value beyond the table's bounds is refused and the old one stays; within them it is
// applied as asked. dynamic_reconfigure used to clamp to the .cfg's tighter bounds first:
// hold_time 20 s (the table allows 30) became 10 s and nothing said so (issue 34).
TEST_F(LiveTuning, OutOfBoundsIsRefusedNeverClamped) {
  const auto longer = call(withDouble("hold_time", 20.0), kControllerService);
  EXPECT_DOUBLE_EQ(doubleOf(longer, "hold_time"), 20.0);
  EXPECT_DOUBLE_EQ(param("hold_time", "velocity_controller"), 20.0);
  const auto beyond = call(withDouble("hold_time", 40.0), kControllerService);
  EXPECT_DOUBLE_EQ(doubleOf(beyond, "hold_time"), 20.0);
  EXPECT_DOUBLE_EQ(param("hold_time", "velocity_controller"), 20.0);
  const auto back = call(withDouble("hold_time", 1.0), kControllerService);
  EXPECT_DOUBLE_EQ(doubleOf(back, "hold_time"), 1.0);
}

// No .cfg field has bounds of its own: dynamic_reconfigure would clamp to them silently
// before the node's validation sees the request. The table's bounds are the only ones.
template <typename Config>
void expectNoCfgBounds() {
  const Config& lo = Config::__getMin__();
  const Config& hi = Config::__getMax__();
  int checked = 0;
  for (const auto& d : Config::__getParamDescriptions__()) {
    boost::any min;
    boost::any max;
    d->getValue(lo, min);
    d->getValue(hi, max);
    if (d->type == "double") {
      EXPECT_EQ(boost::any_cast<double>(min), -std::numeric_limits<double>::infinity()) << d->name;
      EXPECT_EQ(boost::any_cast<double>(max), std::numeric_limits<double>::infinity()) << d->name;
      ++checked;
    } else if (d->type == "int") {
      EXPECT_EQ(boost::any_cast<int>(min), std::numeric_limits<int>::min()) << d->name;
      EXPECT_EQ(boost::any_cast<int>(max), std::numeric_limits<int>::max()) << d->name;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

// Every parameter is declared once (issue 32): a .cfg field's default (what the GUI's
// "reset to defaults" sets) is its parameter table's default, not a second copy that can
// drift from it.
template <typename Config, typename S>
void expectCfgDefaultsFromTheTable(const radio_follow::ParamTable<S>& table) {
  const Config cfg = Config::__getDefault__();
  const Config from_table = radio_follow::tuningFromTable<Config>(table, S{});
  int checked = 0;
  for (const auto& d : Config::__getParamDescriptions__()) {
    if (d->name == radio_follow::kRefusedField) {
      continue;
    }
    boost::any a;
    boost::any b;
    d->getValue(cfg, a);
    d->getValue(from_table, b);
    if (d->type == "double") {
      EXPECT_NEAR(boost::any_cast<double>(a), boost::any_cast<double>(b),
                  1e-9 * std::max(1.0, std::abs(boost::any_cast<double>(b))))
          << d->name << ": the .cfg's default is not the table's";
    } else if (d->type == "int") {
      EXPECT_EQ(boost::any_cast<int>(a), boost::any_cast<int>(b)) << d->name;
    } else if (d->type == "bool") {
      EXPECT_EQ(boost::any_cast<bool>(a), boost::any_cast<bool>(b)) << d->name;
    } else {
      EXPECT_EQ(boost::any_cast<std::string>(a), boost::any_cast<std::string>(b)) << d->name;
    }
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

TEST(LiveTuningDefaults, EveryCfgDefaultIsItsTablesDefault) {
  expectCfgDefaultsFromTheTable<radio_follow::ControllerTuningConfig>(
      radio_follow::control::CommandPipelineParams::table());
  expectCfgDefaultsFromTheTable<radio_follow::FollowLawTuningConfig>(
      radio_follow::control::VelocityLawParams::table());
  expectCfgDefaultsFromTheTable<radio_follow::LocatorTuningConfig>(
      radio_follow::estimation::LocatorConfig::table());
}

TEST(LiveTuningBounds, NoCfgFieldCanBeClamped) {
  expectNoCfgBounds<radio_follow::ControllerTuningConfig>();
  expectNoCfgBounds<radio_follow::FollowLawTuningConfig>();
  expectNoCfgBounds<radio_follow::LocatorTuningConfig>();
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "live_tuning_rostest");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
