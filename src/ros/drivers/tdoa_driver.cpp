// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/drivers/tdoa_driver.hpp"

#include <algorithm>
#include <functional>
#include <utility>

namespace radio_follow {
namespace {

// Depth of the publish queue and of the roscpp publisher queue behind it (a roscpp queue
// that overflows drops its oldest message without telling anyone). One message per blink:
// a tag blinks at up to 10 Hz, a few tags share the anchors; a burst is what the socket's
// receive buffer (212 KiB by default, a few hundred reports) or the grouper (64 open
// blinks, emitted at once when their window passes) hands over at once. 1024 blinks are
// 10 s of ten tags at 10 Hz.
constexpr std::size_t kBlinkQueueDepth = 1024;

// Blinks/s of ten tags at 10 Hz: more on `measurements` is a backlog arriving.
constexpr double kMaxBlinkRate = 100.0;

}  // namespace

TdoaDriverNode::TdoaDriverNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh) {
  params_ = loadStrict<Params>(private_nh);
  receiver_ =
      std::make_unique<drivers::TdoaReceiver>(params_.differenceConfig(), params_.group_window);

  pub_ = nh.advertise<TdoaMeasurements>("measurements", kBlinkQueueDepth);
  queue_ = std::make_unique<drivers::DeliveryQueue<TdoaMeasurements>>(
      kBlinkQueueDepth, [this](TdoaMeasurements& msg) {
        barrier_.run("publish", [&] {
          pub_.publish(msg);
          output_diagnostic_->tick(msg.header.stamp);
          if (blinks_published_++ == 0) {
            ROS_DEBUG_NAMED("wiring", "%s: first blink published on %s",
                            ros::this_node::getName().c_str(), pub_.getTopic().c_str());
          }
        });
      });
  diagnostics_.setHardwareIDf("tdoa udp %s:%d", params_.address.c_str(), params_.port);
  diagnostics_.add("TDoA anchors", this, &TdoaDriverNode::diagnose);
  // A blink is stamped with its first report's arrival and published when its window
  // passes (or when it is complete): a stamp older than data_timeout sat in the queue.
  output_diagnostic_.emplace(
      diagnostics_, "TDoA anchors output", pub_,
      OutputDiagnostic::Bounds::forDriver(params_.data_timeout, kMaxBlinkRate), true);
  last_datagram_ = last_diagnosis_ = ros::WallTime::now();
  // Incomplete blinks are published when their window passes; check twice per window.
  timer_ = barrier_.timer(nh, ros::Duration(params_.group_window / 2.0), "grouping",
                          &TdoaDriverNode::onTimer, this);

  drivers::TdoaUdpTransport::Config config;
  config.address = params_.address;
  config.port = static_cast<std::uint16_t>(params_.port);
  config.initial_backoff = params_.initial_backoff;
  config.max_backoff = params_.max_backoff;
  transport_ = std::make_unique<drivers::TdoaUdpTransport>(
      config,
      [this](const std::uint8_t* data, std::size_t size) {
        barrier_.run("udp input", [&] { onDatagram(data, size); });
      },
      [this](const std::string& what, double retry_in) {
        barrier_.run("socket error", [&] { onSocketError(what, retry_in); });
      });
  transport_->start();
  ROS_INFO("tdoa_driver: listening on %s:%d for %zu anchors (master %s)", params_.address.c_str(),
           params_.port, params_.anchors.size(), params_.master.c_str());
}

TdoaDriverNode::~TdoaDriverNode() {
  // Stop the I/O thread before the members its callbacks touch go away.
  if (transport_) {
    transport_->stop();
  }
  timer_.stop();
  queue_->stop();  // publishes what was queued last
}

void TdoaDriverNode::onDatagram(const std::uint8_t* data, std::size_t size) {
  std::lock_guard<std::mutex> lock(mutex_);
  last_datagram_ = ros::WallTime::now();
  const drivers::TdoaDecodeError error =
      receiver_->onDatagram(data, size, ros::Time::now().toSec(), &blinks_);
  const drivers::TdoaStats& stats = receiver_->stats();
  if (stats.rejected() != last_logged_rejections_) {
    last_logged_rejections_ = stats.rejected();
    // One line per 5 s at most, however many packets are bad.
    ROS_WARN_THROTTLE(5.0, "tdoa_driver: dropped a datagram (%s); %llu of %llu dropped so far",
                      error == drivers::TdoaDecodeError::kOk
                          ? "unknown anchor, missing TLV or duplicate"
                          : toString(error),
                      static_cast<unsigned long long>(stats.rejected()),
                      static_cast<unsigned long long>(stats.packets));
  }
  publish(blinks_);
  blinks_.clear();
}

void TdoaDriverNode::onSocketError(const std::string& what, double retry_in) {
  ROS_WARN_THROTTLE(10.0, "tdoa_driver: %s; retrying in %.1f s", what.c_str(), retry_in);
}

void TdoaDriverNode::onTimer(const ros::TimerEvent&) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    receiver_->onTimer(ros::Time::now().toSec(), &blinks_);
    publish(blinks_);
    blinks_.clear();
    const double silence = (ros::WallTime::now() - last_datagram_).toSec();
    if (silence > params_.data_timeout) {
      ROS_WARN_THROTTLE(5.0, "tdoa_driver: no datagram for %.1f s (socket %s)", silence,
                        transport_->isOpen() ? "open" : "not bound");
    }
  }
  diagnostics_.update();
}

void TdoaDriverNode::publish(const std::vector<drivers::TdoaBlink>& blinks) {
  const auto& anchors = receiver_->config().anchors;
  for (const auto& blink : blinks) {
    TdoaMeasurements msg;
    msg.header.stamp = ros::Time(blink.first_arrival);
    msg.header.frame_id = params_.frame_id;
    msg.tag_id = drivers::tdoaTagIdString(blink.tag);
    for (const auto& d : blink.differences) {
      TdoaDifference out;
      out.anchor_a = anchors[d.anchor_a].id;
      out.anchor_b = anchors[d.anchor_b].id;
      out.distance_difference = d.distance_difference;
      out.variance = d.variance;
      msg.differences.push_back(out);
    }
    if (!queue_->push(std::move(msg))) {
      ++blinks_unpublished_;
      ROS_DEBUG_THROTTLE_NAMED(1.0, "wiring", "tdoa_driver: blink dropped: publish queue full");
    }
  }
}

void TdoaDriverNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  std::lock_guard<std::mutex> lock(mutex_);
  const drivers::TdoaStats& s = receiver_->stats();
  const ros::WallTime now = ros::WallTime::now();
  const double span = std::max((now - last_diagnosis_).toSec(), 1e-3);
  const double silence = (now - last_datagram_).toSec();
  status.add("datagram rate (1/s)", (s.packets - packets_at_last_diagnosis_) / span);
  status.add("blink rate (1/s)", (s.blinks - blinks_at_last_diagnosis_) / span);
  packets_at_last_diagnosis_ = s.packets;
  blinks_at_last_diagnosis_ = s.blinks;
  last_diagnosis_ = now;
  status.add("datagrams", s.packets);
  status.add("blinks formed", s.blinks);
  status.add("blinks published", blinks_published_.load());
  status.add("blinks published incomplete", s.blinks_incomplete);
  status.add("blinks dropped", s.blinks_dropped);
  status.add("blinks dropped: publish queue full", blinks_unpublished_);
  status.add("publish queue peak", queue_->peak());
  status.add("implausible differences", s.implausible_differences);
  status.add("rejected", s.rejected());
  for (std::size_t i = 1; i < drivers::kTdoaDecodeErrorCount; ++i) {
    status.add(std::string("rejected: ") + toString(static_cast<drivers::TdoaDecodeError>(i)),
               s.decode_errors[i]);
  }
  status.add("rejected: unknown_anchor", s.unknown_anchor);
  status.add("rejected: missing_tlv", s.missing_tlv);
  status.add("rejected: duplicate", s.duplicate);
  status.add("socket open", transport_->isOpen());
  status.add("local port", transport_->localPort());
  status.add("reconnects", transport_->reconnects());
  status.add("socket failures", transport_->failures());
  status.add("seconds since last datagram", silence);
  if (!transport_->isOpen()) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "socket not bound, retrying");
  } else if (silence > params_.data_timeout) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no data from the anchors");
  } else if (blinks_unpublished_ > unpublished_at_last_diagnosis_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "dropping blinks: publish queue full");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "receiving");
  }
  unpublished_at_last_diagnosis_ = blinks_unpublished_;
}

}  // namespace radio_follow
