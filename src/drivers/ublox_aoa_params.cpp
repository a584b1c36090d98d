// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/ublox_aoa_params.hpp"

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/drivers/text_fields.hpp"

namespace radio_follow::drivers {

const ParamTable<UbloxAoaParams>& UbloxAoaParams::table() {
  using P = UbloxAoaParams;
  static const ParamTable<P> t =
      ParamTable<P>()
          .includeBase(SerialLineParams::table())
          .add("frame_id", &P::frame_id, "", "The board's frame: x = boresight (required).")
          .add("invert_azimuth", &P::invert_azimuth, "",
               "Publish the device's clockwise azimuth counter-clockwise (REP 103).");
  return t;
}

void UbloxAoaParams::load(const ParamSource& source) {
  table().load(source, *this);
  source.param("tag_ids", tag_ids, tag_ids);
  source.param("init_commands", init_commands, init_commands);
  // The device reports IDs in upper case; accept either spelling in the config.
  for (std::string& id : tag_ids) {
    assignUpperHex(std::string(id), id);
  }
}

void UbloxAoaParams::validate() const {
  require(!port.empty(), "~port", port, "a device path such as /dev/aoa_front");
  table().check(*this);
  require(!frame_id.empty(), "~frame_id", frame_id, "the antenna board's frame name");
  for (const std::string& id : tag_ids) {
    require(isHexId(id, 12), "~tag_ids", id, "12 hexadecimal digits per tag");
  }
  for (const std::string& command : init_commands) {
    require(!command.empty() && command.find_first_of("\r\n") == std::string::npos,
            "~init_commands", command, "one AT command per entry, without line ends");
  }
}

}  // namespace radio_follow::drivers
