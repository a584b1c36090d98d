// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/ros/drivers/layout_drivers.hpp"

#include <utility>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace {

// The private namespaces of the settings all devices of a kind share.
constexpr const char* kModuleNamespace = "dwm1001";
constexpr const char* kBoardNamespace = "ublox_aoa";

// A per-device key set in a shared namespace would be silently replaced by the layout's.
void requireUnset(const std::string& ns, const char* key, const std::string& value) {
  require(value.empty(), "~" + ns + "/" + key, value,
          "nothing: layout_drivers takes it per device from the layout");
}

template <typename Params>
Params loadShared(const ros::NodeHandle& private_nh, const std::string& ns) {
  const ParamReader reader(ros::NodeHandle(private_nh, ns), "~" + ns + "/");
  Params params;
  params.load(reader);
  reader.requireAllKnown();
  return params;
}

}  // namespace

const ParamTable<LayoutDriversNode::Params>& LayoutDriversNode::Params::table() {
  using P = LayoutDriversNode::Params;
  static const ParamTable<P> t =
      ParamTable<P>()
          .add("layout_file", &P::layout_file, "", "Absolute path of the robot's layout.")
          .add("uwb_port_prefix", &P::uwb_port_prefix, "", "A module's device is this plus its ID.")
          .add("aoa_port_prefix", &P::aoa_port_prefix, "", "A board's device is this plus its ID.");
  return t;
}

void LayoutDriversNode::Params::load(const ParamReader& private_nh) {
  table().load(private_nh, *this);
  private_nh.own(kModuleNamespace);
  private_nh.own(kBoardNamespace);
}

void LayoutDriversNode::Params::validate() const {
  require(!layout_file.empty(), "~layout_file", layout_file,
          "the absolute path of the robot's layout YAML");
  require(!uwb_port_prefix.empty(), "~uwb_port_prefix", uwb_port_prefix,
          "a device path prefix, e.g. /dev/dwm1001_");
  require(!aoa_port_prefix.empty(), "~aoa_port_prefix", aoa_port_prefix,
          "a device path prefix, e.g. /dev/aoa_");
}

Dwm1001DriverNode::Params moduleDriverParams(const Dwm1001DriverNode::Params& shared,
                                             const TwrModule& module,
                                             const std::string& port_prefix) {
  requireUnset(kModuleNamespace, "port", shared.port);
  requireUnset(kModuleNamespace, "tag_id", shared.tag_id);
  requireUnset(kModuleNamespace, "frame_id", shared.frame_id);
  Dwm1001DriverNode::Params params = shared;
  params.port = port_prefix + module.id;
  params.tag_id = module.id;
  params.frame_id = module.frame_id;
  params.validate();
  return params;
}

UbloxAoaDriverNode::Params boardDriverParams(const UbloxAoaDriverNode::Params& shared,
                                             const AoaBoard& board, const Layout& layout,
                                             const std::string& port_prefix) {
  requireUnset(kBoardNamespace, "port", shared.port);
  requireUnset(kBoardNamespace, "frame_id", shared.frame_id);
  UbloxAoaDriverNode::Params params = shared;
  params.port = port_prefix + board.id;
  params.frame_id = board.frame_id;
  if (params.tag_ids.empty() && !layout.target_tag_id.empty()) {
    params.tag_ids = {layout.target_tag_id};
  }
  params.validate();
  return params;
}

LayoutDriversNode::LayoutDriversNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh) {
  const Params params = loadStrict<Params>(private_nh);
  const Layout layout = loadLayoutFile(params.layout_file);
  const auto module_shared = loadShared<Dwm1001DriverNode::Params>(private_nh, kModuleNamespace);
  const auto board_shared = loadShared<UbloxAoaDriverNode::Params>(private_nh, kBoardNamespace);

  // Every device's parameters are checked before the first port opens.
  std::vector<Dwm1001DriverNode::Params> module_params;
  for (const TwrModule& module : layout.twr_modules) {
    module_params.push_back(moduleDriverParams(module_shared, module, params.uwb_port_prefix));
  }
  std::vector<UbloxAoaDriverNode::Params> board_params;
  for (const AoaBoard& board : layout.aoa_boards) {
    board_params.push_back(boardDriverParams(board_shared, board, layout, params.aoa_port_prefix));
  }
  if (module_params.empty() && board_params.empty()) {
    throw ParamError("~layout_file", params.layout_file,
                     "a layout with twr_modules or aoa_boards (its TDoA anchors are not serial "
                     "devices: start tdoa_driver.launch)");
  }

  // The node handles live as long as the drivers; reserve so that none moves.
  handles_.reserve(2 * (module_params.size() + board_params.size()));
  for (const auto& module : module_params) {
    ros::NodeHandle& ns = handles_.emplace_back(nh, uwbNamespace(module.tag_id));
    ros::NodeHandle& own = handles_.emplace_back(private_nh, kModuleNamespace);
    modules_.push_back(std::make_unique<Dwm1001DriverNode>(ns, own, module));
    ports_.push_back(module.port);
  }
  for (std::size_t i = 0; i < board_params.size(); ++i) {
    ros::NodeHandle& ns = handles_.emplace_back(nh, aoaNamespace(layout.aoa_boards[i].id));
    ros::NodeHandle& own = handles_.emplace_back(private_nh, kBoardNamespace);
    boards_.push_back(std::make_unique<UbloxAoaDriverNode>(ns, own, board_params[i]));
    ports_.push_back(board_params[i].port);
  }
  ROS_INFO("%s: %zu DWM1001 module(s) and %zu AoA board(s) of %s on %s*, %s*",
           ros::this_node::getName().c_str(), modules_.size(), boards_.size(),
           params.layout_file.c_str(), params.uwb_port_prefix.c_str(),
           params.aoa_port_prefix.c_str());
}

}  // namespace radio_follow
