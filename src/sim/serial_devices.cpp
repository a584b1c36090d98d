// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/serial_devices.hpp"

#include <cmath>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace sim {

UudfEvent toUudf(const AoaSample& sample, const std::string& tag_id, const std::string& anchor_id,
                 double t) {
  UudfEvent e;
  e.tag_id = tag_id;
  e.rssi = static_cast<int>(std::lround(sample.rssi));
  e.azimuth = static_cast<int>(std::lround(-rad2deg(sample.azimuth)));
  e.elevation = static_cast<int>(std::lround(rad2deg(sample.elevation)));
  e.rssi_second = static_cast<int>(std::lround(sample.rssi_second));
  e.channel = 37;
  e.anchor_id = anchor_id;
  e.timestamp_ms = static_cast<std::uint32_t>(t * 1000.0);
  return e;
}

SerialDevices::SerialDevices(const Layout& layout, const std::string& directory,
                             std::vector<UnplugFault> faults)
    : layout_(layout), directory_(directory), faults_(std::move(faults)) {
  auto make = [this](const std::string& name) {
    Device d;
    d.name = name;
    d.pty = std::make_unique<PtyDevice>(pathOf(name));
    require(d.pty->plug(), "~serial_dir", directory_,
            "a writable directory for the device links (" + d.pty->error() + ")");
    return d;
  };
  for (const auto& m : layout_.twr_modules) {
    Device d = make("uwb_" + m.id);
    d.shell = std::make_unique<DwmShellEmulator>(m.id);
    uwb_.push_back(std::move(d));
  }
  for (const auto& b : layout_.aoa_boards) {
    aoa_.push_back(make("aoa_" + b.id));
  }
  for (std::size_t i = 0; i < faults_.size(); ++i) {
    const auto& f = faults_[i];
    bool known = false;
    for (const auto* list : {&uwb_, &aoa_}) {
      for (const auto& d : *list)
        known = known || d.name == f.device;
    }
    const std::string name = "~unplug[" + std::to_string(i) + "]";
    require(known, name + ".device", f.device,
            "a simulated device: uwb_<module id> or aoa_<board id>");
    require(f.at >= 0.0 && f.duration > 0.0, name + ".duration", f.duration,
            "at >= 0 and duration > 0 seconds");
  }
}

std::string SerialDevices::pathOf(const std::string& device) const {
  return directory_ + "/" + device;
}

void SerialDevices::service(double t) {
  now_ = t;
  for (auto* list : {&uwb_, &aoa_}) {
    for (auto& d : *list) {
      bool absent = false;
      for (const auto& f : faults_) {
        absent = absent || (f.device == d.name && t >= f.at && t < f.at + f.duration);
      }
      if (absent && d.pty->plugged()) {
        d.pty->unplug();
      } else if (!absent && !d.pty->plugged()) {
        d.pty->plug();
        if (d.shell) {
          // A replugged module has rebooted: it is back in API mode.
          d.shell = std::make_unique<DwmShellEmulator>(d.name.substr(std::string("uwb_").size()));
        }
      }
    }
  }
  for (auto& d : uwb_) {
    const std::string input = d.pty->read();
    if (!input.empty()) {
      d.pty->write(d.shell->receive(input, t));
    }
  }
  for (auto& d : aoa_) {
    d.pty->read();  // AT commands: the board streams regardless; nothing to answer here
  }
}

void SerialDevices::write(const StepEvents& events) {
  for (const auto& e : events.twr) {
    Device& d = uwb_[e.module];
    const std::vector<DwmAnchorRange> ranges{
        {layout_.target_anchor_id, Eigen::Vector3d::Zero(), e.range}};
    d.pty->write(d.shell->epoch(ranges, std::nullopt, e.t));
  }
  const std::string tag = layout_.target_tag_id.empty() ? "CCF9578E0D8A" : layout_.target_tag_id;
  for (const auto& e : events.aoa) {
    Device& d = aoa_[e.board];
    d.pty->write(formatUudfLine(toUudf(e.sample, tag, layout_.aoa_boards[e.board].id, e.t)) +
                 "\r\n");
  }
}

std::size_t SerialDevices::droppedBytes() const {
  std::size_t total = 0;
  for (const auto* list : {&uwb_, &aoa_}) {
    for (const auto& d : *list)
      total += d.pty->droppedBytes();
  }
  return total;
}

}  // namespace sim
}  // namespace radio_follow
