// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/control/command_pipeline.hpp"

#include <cmath>
#include <string>

#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"
#include "radio_follow/common/plausibility.hpp"

namespace radio_follow {
namespace control {

const ParamTable<CommandPipelineParams>& CommandPipelineParams::table() {
  using P = CommandPipelineParams;
  static const ParamTable<P> t =
      ParamTable<P>()
          .include(SafetyParams::table(), &P::safety)
          .include(MotionLimits::table(), &P::limits)
          .add("use_scan", &P::use_scan, "", "Enable laser-scan avoidance.")
          .add("scan_timeout", &P::scan_timeout, "s", "Older scan = forward motion blocked.",
               Range::above(0.0))
          .include(AvoidanceParams::table(), &P::avoidance)
          .add("calibrate_ranges", &P::calibrate_ranges, "",
               "Apply each module's layout calibration to its ranges before the stop check.")
          .add("target_anchor_id", &P::target_anchor_id, "",
               "Target's anchor (case-insensitive); empty = any anchor.");
  return t;
}

void CommandPipelineParams::load(const ParamSource& p, const Layout* layout) {
  table().load(p, *this, "calibrate_ranges");
  if (layout != nullptr) {
    // Explicit parameters below still win over what the layout implies.
    target_anchor_id = layout->target_anchor_id;
    calibrated_modules.clear();
    if (calibrate_ranges) {
      for (const TwrModule& module : layout->twr_modules) {
        calibrated_modules[module.id] = module;  // normalised by the parser
      }
    }
  }
  table().load(p, *this);  // target_anchor_id: the layout's unless set
  target_anchor_id = normalizeId(target_anchor_id);
}

void CommandPipelineParams::validate() const {
  table().check(*this);
  // A calibration that moves the stop threshold far, or turns it around, is more likely a
  // typo in the layout than a module: the safety stop must not silently depend on it.
  const double d = safety.safe_distance;
  for (const auto& [id, module] : calibrated_modules) {
    const double shift = module.correctRange(d) - d;
    const double slope = (module.correctRange(d + 0.1) - module.correctRange(d)) / 0.1;
    require(std::abs(shift) <= kMaxSafetyCalibrationShift && slope > 0.5 && slope < 2.0,
            "~layout_file twr_modules[" + id + "].calibration", module.correctRange(d),
            "a corrected range at safe_distance (" + std::to_string(d) + " m) within " +
                std::to_string(kMaxSafetyCalibrationShift) +
                " m of it and a slope in (0.5, 2) there (or ~calibrate_ranges: false)");
  }
  safety.validate();
  limits.validate();
  avoidance.validate();
}

CommandPipeline::CommandPipeline(const CommandPipelineParams& params)
    : params_(params), monitor_(params.safety), limiter_(params.limits) {}

bool CommandPipeline::onRange(double stamp, double now, const std::string& source,
                              const std::string& module_id, const std::string& anchor_id,
                              double raw_range) {
  if (!params_.target_anchor_id.empty() && normalizeId(anchor_id) != params_.target_anchor_id) {
    return false;
  }
  // The drivers' bounds hold here too: a value no module can report (inf, 1e300, NaN,
  // negative) is a faulty publisher, never a live range (issue 34).
  if (!plausibleRange(raw_range)) {
    monitor_.onImplausibleRange(now);
    return true;
  }
  const auto module = params_.calibrated_modules.find(normalizeId(module_id));
  const double range = module == params_.calibrated_modules.end()
                           ? raw_range
                           : module->second.correctRange(raw_range);
  return monitor_.onRange(stamp, now, source, range);
}

bool CommandPipeline::onEstimate(double stamp, double now, EstimateQuality quality) {
  return monitor_.onEstimate(stamp, now, quality);
}

void CommandPipeline::onScan(const SectorRanges& sectors, double stamp) {
  sectors_ = sectors;
  scan_stamp_ = stamp;
}

PipelineResult CommandPipeline::finish(const LawOutput& out, double now, double dt) {
  PipelineResult result;
  VelocityCommand request = out.command;
  result.text = out.text;
  if (params_.use_scan) {
    if (sectors_ && now - scan_stamp_ <= params_.scan_timeout) {
      request = avoidObstacles(request, *sectors_, params_.avoidance);
    } else {
      // Avoidance was asked for but cannot see: turning in place is the only safe motion.
      request.linear = 0.0;
      result.text = "No laser scan, not driving.";
      result.scan_missing = true;
    }
  }
  // The law may have run while a range stopped the robot: the verdict is taken again,
  // at the time of sending.
  const SafetyDecision decision = monitor_.evaluate(now);
  if (!decision.may_move) {
    PipelineResult stopped = stop(decision.reason);
    stopped.scan_missing = result.scan_missing;
    return stopped;
  }
  result.command = gateCommand(decision, limiter_.update(request, dt));
  result.state = out.state;
  if (result.text.empty()) {
    result.text = defaultText(out.state);
  }
  result.moving = true;
  return result;
}

PipelineResult CommandPipeline::stop(StopReason reason) {
  limiter_.reset();
  PipelineResult result;
  result.state = stateFor(reason);
  result.text = stopText(reason);
  return result;
}

double CommandPipeline::moduleGap(double now) const {
  return monitor_.nearestRange(now) - monitor_.params().safe_distance;
}

void CommandPipeline::setParams(const CommandPipelineParams& params) {
  params.limits.validate();           // both checked before anything changes
  monitor_.setParams(params.safety);  // validates the thresholds
  limiter_.setLimits(params.limits);
  params_ = params;
}

}  // namespace control
}  // namespace radio_follow
