// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/drivers/dwm1001_params.hpp"

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"

namespace radio_follow::drivers {

const ParamTable<Dwm1001Params>& Dwm1001Params::table() {
  using P = Dwm1001Params;
  static const ParamTable<P> t =
      ParamTable<P>()
          .includeBase(SerialLineParams::table())
          .add("configure", &P::configure, "",
               "Run the shell dialogue on every (re)connect; false: only listen.")
          .addChoice(
              "output_mode", &P::output_mode,
              std::vector<std::pair<std::string, std::string>>{{"lec", "lec"}, {"les", "les"}},
              "Stream command: lec (CSV) or les (text).")
          .add("tag_id", &P::tag_id, "", "Module ID when configure is false.")
          .add("frame_id", &P::frame_id, "", "Frame of ranges; empty: uwb_<module ID>.")
          .add("network_frame_id", &P::network_frame_id, "", "Frame of tag_location.")
          .add("shell_timeout", &P::shell_timeout, "s",
               "Time one dialogue step may take before the dialogue restarts.", Range::above(0.0));
  return t;
}

void Dwm1001Params::load(const ParamSource& source) {
  table().load(source, *this);
  tag_id = normalizeId(tag_id);  // IDs enter normalised (upper case), as the layout's
}

void Dwm1001Params::validate() const {
  require(!port.empty(), "~port", port, "a device path such as /dev/dwm1001_5722");
  table().check(*this);
  require(configure || !frame_id.empty() || !tag_id.empty(), "~frame_id", frame_id,
          "a frame (or a tag_id to derive it from) when configure is false");
  require(!network_frame_id.empty(), "~network_frame_id", network_frame_id, "a frame name");
}

}  // namespace radio_follow::drivers
