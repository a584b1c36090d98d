// SPDX-License-Identifier: BSD-3-Clause
// Plays three TDoA anchors on loopback: blinks of a tag at a known position, encoded
// with the test packet builder, interleaved with malformed datagrams. Checks the
// published distance differences and that the bad datagrams are counted in the
// diagnostics without interrupting the stream.
#include "radio_follow/ros/drivers/tdoa_driver.hpp"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <radio_follow/TdoaMeasurements.h>
#include <ros/ros.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>
#include <cmath>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/drivers/tdoa_differences.hpp"
#include "radio_follow/drivers/tdoa_packet.hpp"
#include "radio_follow/drivers/tdoa_packet_builder.hpp"

namespace radio_follow {
namespace {

using boost::asio::ip::udp;

struct Anchor {
  std::string id;
  std::uint64_t address;
  Eigen::Vector3d position;
};

// config/tdoa_driver.yaml; master "05", the launch file sets reference "17".
const std::vector<Anchor> kAnchors{{"05", 0x2000, {0.29, 0.165, 0.135}},
                                   {"49", 0x2002, {0.29, -0.165, 0.135}},
                                   {"17", 0x2001, {-0.37, 0.0, 0.135}}};
const Eigen::Vector3d kTag(2.5, 1.2, 0.9);
constexpr std::uint16_t kTagId = 0x5A84;

std::uint64_t rxTicks(const Anchor& a, double t0) {
  const double flight = (kTag - a.position).norm() / drivers::kSpeedOfLight;
  const double sync_lag = (a.position - kAnchors[0].position).norm() / drivers::kSpeedOfLight;
  return static_cast<std::uint64_t>(std::llround((t0 + flight - sync_lag) * drivers::kTdoaTickFrequency));
}

double expectedDifference(const std::string& a, const std::string& b) {
  auto position = [](const std::string& id) {
    for (const auto& anchor : kAnchors) {
      if (anchor.id == id) {
        return anchor.position;
      }
    }
    ADD_FAILURE() << "unknown anchor " << id;
    return Eigen::Vector3d(0, 0, 0);
  };
  return (kTag - position(a)).norm() - (kTag - position(b)).norm();
}

class Anchors {
 public:
  explicit Anchors(int port)
      : socket_(io_, udp::v4()),
        target_(boost::asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port)) {}

  void send(const std::vector<std::uint8_t>& bytes) {
    socket_.send_to(boost::asio::buffer(bytes), target_);
  }

  // One blink heard by every anchor.
  void blink(std::uint8_t seq) {
    const double t0 = 20.0 + 0.1 * seq;
    for (const auto& a : kAnchors) {
      send(drivers::TdoaPacketBuilder(a.address, seq).mac(kTagId).timestamp(rxTicks(a, t0)).build());
    }
  }

  // Malformed datagram number k (five kinds, one per rejection reason).
  void bad(int k) {
    const std::uint64_t anchor = kAnchors[1].address;
    switch (k % 5) {
      case 0:
        send({0xDE, 0xAD, 0xBE, 0xEF});  // no magic
        break;
      case 1: {
        auto bytes = drivers::TdoaPacketBuilder(anchor, 1).mac(kTagId).timestamp(1).build();
        bytes.resize(20);  // too short
        send(bytes);
        break;
      }
      case 2:
        send(drivers::TdoaPacketBuilder(anchor, 1).mac(kTagId).timestamp(1).lengthField(500).build());
        break;
      case 3:
        send(drivers::TdoaPacketBuilder(anchor, 1).rawTlv(2, {1, 2}, 4000).build());  // TLV overrun
        break;
      default:
        send(drivers::TdoaPacketBuilder(0x7777, 1).mac(kTagId).timestamp(1).build());  // unknown
        break;
    }
  }

 private:
  boost::asio::io_context io_;
  udp::socket socket_;
  udp::endpoint target_;
};

struct Received {
  std::mutex mutex;
  std::vector<TdoaMeasurements> blinks;
  std::map<std::string, std::string> diagnostics;  // latest values of our status

  long long diagnostic(const std::string& key) {
    std::lock_guard<std::mutex> lock(mutex);
    const auto it = diagnostics.find(key);
    return it == diagnostics.end() ? -1 : std::stoll(it->second);
  }
};

TEST(TdoaDriver, PublishesDifferencesAndCountsBadDatagramsWithoutStopping) {
  ros::NodeHandle nh;
  Received received;
  // A deep queue: the test's own subscriber must not be what loses a blink.
  ros::Subscriber sub = nh.subscribe<TdoaMeasurements>(
      "measurements", 100000, [&](const TdoaMeasurements::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(received.mutex);
        received.blinks.push_back(*msg);
      });
  ros::Subscriber diag = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
        for (const auto& status : msg->status) {
          if (status.name.find("TDoA anchors") == std::string::npos) {
            continue;
          }
          std::lock_guard<std::mutex> lock(received.mutex);
          for (const auto& kv : status.values) {
            received.diagnostics[kv.key] = kv.value;
          }
        }
      });
  // The node binds port 0 (any free port) and reports the kernel's choice.
  const ros::WallTime bind_deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  while (received.diagnostic("local port") <= 0 && ros::WallTime::now() < bind_deadline) {
    ros::WallDuration(0.1).sleep();
  }
  const long long port = received.diagnostic("local port");
  ASSERT_GT(port, 0) << "the driver did not report a bound port within 30 s";
  Anchors anchors(static_cast<int>(port));
  auto count = [&] {
    std::lock_guard<std::mutex> lock(received.mutex);
    return received.blinks.size();
  };

  // The node binds on its own thread: send until the first blink comes back.
  std::uint8_t seq = 0;
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(30.0);
  while (count() == 0 && ros::WallTime::now() < give_up) {
    anchors.blink(seq++);
    ros::WallDuration(0.1).sleep();
  }
  ASSERT_GT(count(), 0u) << "no TdoaMeasurements within 30 s";

  // 300 blinks (the sequence number wraps) with a bad datagram before each, 100 a second:
  // the socket's default receive buffer holds far more than a loaded machine's stall.
  const std::size_t before = count();
  constexpr int kBlinks = 300;
  for (int i = 0; i < kBlinks; ++i) {
    anchors.bad(i);
    anchors.blink(seq++);
    ros::WallDuration(0.01).sleep();
  }
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
  while (count() < before + kBlinks && ros::WallTime::now() < deadline) {
    ros::WallDuration(0.05).sleep();
  }
  // Diagnostics are published about once a second; wait for one that saw everything.
  const ros::WallTime diag_deadline = ros::WallTime::now() + ros::WallDuration(20.0);
  while (received.diagnostic("rejected") < kBlinks && ros::WallTime::now() < diag_deadline) {
    ros::WallDuration(0.1).sleep();
  }
  EXPECT_EQ(received.diagnostic("rejected"), kBlinks);
  for (const char* reason :
       {"no_magic", "too_short", "length_beyond_packet", "tlv_overrun", "unknown_anchor"}) {
    EXPECT_EQ(received.diagnostic(std::string("rejected: ") + reason), kBlinks / 5) << reason;
  }
  EXPECT_EQ(received.diagnostic("reconnects"), 0);

  std::lock_guard<std::mutex> lock(received.mutex);
  ASSERT_EQ(received.blinks.size(), before + kBlinks);
  const double tick_metres = drivers::kSpeedOfLight / drivers::kTdoaTickFrequency;
  for (const auto& msg : received.blinks) {
    EXPECT_EQ(msg.tag_id, "5A84");
    EXPECT_EQ(msg.header.frame_id, "base_link");
    ASSERT_EQ(msg.differences.size(), 2u);
    for (const auto& d : msg.differences) {
      EXPECT_EQ(d.anchor_b, "17");
      EXPECT_NEAR(d.distance_difference, expectedDifference(d.anchor_a, d.anchor_b), tick_metres);
      EXPECT_DOUBLE_EQ(d.variance, 0.0225);
    }
  }
}

// Parameter loading and validation against a live parameter server (no node started).
class TdoaDriverParams : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* key :
         {"anchors", "master", "reference", "port", "group_window", "max_backoff", "min_anchors"}) {
      nh_.deleteParam(key);
    }
    XmlRpc::XmlRpcValue anchors;
    for (int i = 0; i < 3; ++i) {
      XmlRpc::XmlRpcValue a;
      a["id"] = kAnchors[i].id;
      a["address"] = "0x" + std::to_string(2000 + i);
      XmlRpc::XmlRpcValue position;
      for (int k = 0; k < 3; ++k) {
        position[k] = kAnchors[i].position[k];
      }
      position[2] = 1;  // an int must be accepted as a coordinate
      a["position"] = position;
      anchors[i] = a;
    }
    nh_.setParam("anchors", anchors);
    nh_.setParam("master", "49");
    anchors_ = anchors;
  }

  TdoaDriverNode::Params load() {
    TdoaDriverNode::Params p;
    p.load(ParamReader(nh_));
    p.validate();
    return p;
  }

  // The ParamError's parameter name, or "" if loading succeeded.
  std::string failingParam() {
    try {
      load();
    } catch (const ParamError& e) {
      return e.name();
    }
    return "";
  }

  ros::NodeHandle nh_{"tdoa_params_test"};
  XmlRpc::XmlRpcValue anchors_;
};

TEST_F(TdoaDriverParams, LoadsAnchorsAndResolvesIds) {
  const TdoaDriverNode::Params p = load();
  ASSERT_EQ(p.anchors.size(), 3u);
  EXPECT_EQ(p.anchors[2].address, 0x2002u);
  EXPECT_DOUBLE_EQ(p.anchors[1].position.y(), -0.165);
  EXPECT_DOUBLE_EQ(p.anchors[1].position.z(), 1.0);
  const drivers::TdoaDifferenceConfig c = p.differenceConfig();
  EXPECT_EQ(c.master, 1u);
  EXPECT_EQ(c.reference, 1u);  // empty reference = master
}

TEST_F(TdoaDriverParams, RejectsInvalidValuesNamingTheParameter) {
  nh_.setParam("master", "nope");
  EXPECT_EQ(failingParam(), "~master");
  SetUp();
  nh_.setParam("reference", "nope");
  EXPECT_EQ(failingParam(), "~reference");
  SetUp();
  nh_.setParam("port", 70000);
  EXPECT_EQ(failingParam(), "~port");
  SetUp();
  nh_.setParam("group_window", 0.0);
  EXPECT_EQ(failingParam(), "~group_window");
  SetUp();
  nh_.setParam("max_backoff", 0.1);
  EXPECT_EQ(failingParam(), "~max_backoff");
  SetUp();
  nh_.setParam("min_anchors", 4);
  EXPECT_EQ(failingParam(), "~min_anchors");
  SetUp();
  anchors_[1]["address"] = "0xZZ";
  nh_.setParam("anchors", anchors_);
  EXPECT_EQ(failingParam(), "~anchors[1].address");
  SetUp();
  nh_.setParam("anchors", 5);
  EXPECT_EQ(failingParam(), "~anchors");
  SetUp();
  nh_.deleteParam("anchors");
  EXPECT_EQ(failingParam(), "~anchors");
}

}  // namespace
}  // namespace radio_follow

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "tdoa_driver_rostest");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
