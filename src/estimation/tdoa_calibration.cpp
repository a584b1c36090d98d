// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/tdoa_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "radio_follow/common/median.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/common/param_keys.hpp"

namespace radio_follow {
namespace estimation {

void TdoaCalibrationConfig::validate() const {
  require(std::isfinite(window) && window > 0.0 && window <= 600.0, "~tdoa_calibration_window",
          window, "seconds in (0, 600]");
  require(min_blinks >= 1 && min_blinks <= 100000, "~tdoa_calibration_min_blinks", min_blinks,
          "an integer in [1, 100000]");
}

TdoaCalibration::TdoaCalibration(const Layout& layout, const TdoaCalibrationConfig& config)
    : layout_(layout), config_(config) {
  config_.validate();
}

void TdoaCalibration::setConfig(const TdoaCalibrationConfig& config) {
  config.validate();
  config_ = config;
  for (Window& w : windows_) {
    refresh(w);
  }
}

bool TdoaCalibration::active() const {
  return config_.enabled && !layout_.twr_modules.empty() && layout_.tdoa_anchors.size() >= 2;
}

std::optional<std::size_t> TdoaCalibration::moduleOf(const std::string& tag_id) const {
  const std::string id = normalizeId(tag_id);
  for (std::size_t i = 0; i < layout_.twr_modules.size(); ++i) {
    if (layout_.twr_modules[i].id == id) {
      return i;
    }
  }
  return std::nullopt;
}

bool TdoaCalibration::add(std::size_t module, std::size_t a, std::size_t b, double difference,
                          double t) {
  const std::size_t anchors = layout_.tdoa_anchors.size();
  if (module >= layout_.twr_modules.size() || a >= anchors || b >= anchors || a == b ||
      !std::isfinite(difference) || !std::isfinite(t)) {
    return false;
  }
  const Eigen::Vector3d& m = layout_.twr_modules[module].position;
  const double known =
      (m - layout_.tdoa_anchors[a].position).norm() - (m - layout_.tdoa_anchors[b].position).norm();
  Window* w = find(a, b);
  if (w == nullptr) {
    windows_.push_back(Window{a, b, {}, t, std::nullopt});
    w = &windows_.back();
  }
  // Kept in the orientation first seen (the driver's: anchor - reference): b - a = -(a - b).
  const double residual = w->a == a ? difference - known : known - difference;
  // Stamps arrive nearly in order (one driver, several tags): insert in place.
  auto at = w->residuals.end();
  while (at != w->residuals.begin() && std::prev(at)->first > t) {
    --at;
  }
  w->residuals.insert(at, {t, residual});
  w->newest = std::max(w->newest, t);
  refresh(*w);
  return true;
}

std::optional<double> TdoaCalibration::offset(std::size_t a, std::size_t b) const {
  const Window* w = find(a, b);
  if (w == nullptr || !w->offset) {
    return std::nullopt;
  }
  return w->a == a ? *w->offset : -*w->offset;
}

std::vector<TdoaCalibration::Pair> TdoaCalibration::pairs() const {
  std::vector<Pair> out;
  for (const Window& w : windows_) {
    out.push_back(Pair{w.a, w.b, w.residuals.size(), w.offset});
  }
  return out;
}

TdoaCalibration::Window* TdoaCalibration::find(std::size_t a, std::size_t b) {
  return const_cast<Window*>(static_cast<const TdoaCalibration*>(this)->find(a, b));
}

const TdoaCalibration::Window* TdoaCalibration::find(std::size_t a, std::size_t b) const {
  for (const Window& w : windows_) {
    if ((w.a == a && w.b == b) || (w.a == b && w.b == a)) {
      return &w;
    }
  }
  return nullptr;
}

void TdoaCalibration::refresh(Window& w) const {
  while (!w.residuals.empty() && w.residuals.front().first < w.newest - config_.window) {
    w.residuals.pop_front();
  }
  if (w.residuals.size() < static_cast<std::size_t>(config_.min_blinks)) {
    w.offset.reset();
    return;
  }
  std::vector<double> values;
  values.reserve(w.residuals.size());
  for (const auto& r : w.residuals) {
    values.push_back(r.second);
  }
  w.offset = median(std::move(values));
}

}  // namespace estimation
}  // namespace radio_follow
