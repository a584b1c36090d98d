// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/sim/dwm_shell_emulator.hpp"
#include "radio_follow/sim/pty_device.hpp"
#include "radio_follow/sim/world.hpp"

namespace radio_follow {
namespace sim {

/// A scheduled unplug of one simulated device: it vanishes at `at` seconds for
/// `duration` seconds, then comes back at the same path.
struct UnplugFault {
  std::string device;  ///< "uwb_<module id>" or "aoa_<board id>"
  double at = 0.0;
  double duration = 0.0;
};

/// The simulator's serial mode: every UWB module and AoA board of the layout becomes a
/// pseudo-terminal at `<directory>/uwb_<id>` or `<directory>/aoa_<id>` that speaks the real
/// protocol (the DWM1001 shell dialogue and `lec`/`les`/`lep` lines; `+UUDF` events), so
/// the unchanged driver nodes run in the loop. Faults unplug and replug devices.
class SerialDevices {
 public:
  /// Throws ParamError when a fault names an unknown device or a terminal cannot be made.
  SerialDevices(const Layout& layout, const std::string& directory,
                std::vector<UnplugFault> faults);

  /// Answers what the drivers wrote (shell commands) and applies faults due by time t.
  void service(double t);
  /// Writes the step's measurements as protocol lines.
  void write(const StepEvents& events);

  /// Path of a device, e.g. pathOf("uwb_5722").
  std::string pathOf(const std::string& device) const;
  std::size_t droppedBytes() const;

 private:
  struct Device {
    std::string name;
    std::unique_ptr<PtyDevice> pty;
    std::unique_ptr<DwmShellEmulator> shell;  ///< UWB modules only
  };

  Layout layout_;
  std::string directory_;
  std::vector<Device> uwb_;
  std::vector<Device> aoa_;
  std::vector<UnplugFault> faults_;
  double now_ = 0.0;
};

/// A +UUDF event for a simulated bearing, in the device's conventions (clockwise
/// azimuth, whole degrees and dBm).
UudfEvent toUudf(const AoaSample& sample, const std::string& tag_id, const std::string& anchor_id,
                 double t);

}  // namespace sim
}  // namespace radio_follow
