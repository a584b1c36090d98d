// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/aoa_selector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace estimation {

AoaSelectionMode parseAoaSelectionMode(const std::string& text, const std::string& parameter) {
  if (text == "rssi")
    return AoaSelectionMode::kRssi;
  if (text == "external")
    return AoaSelectionMode::kExternal;
  if (text == "all_in_fov")
    return AoaSelectionMode::kAllInFov;
  throw ParamError(parameter, paramValueString(text), "one of rssi, external, all_in_fov");
}

std::string toString(AoaSelectionMode mode) {
  switch (mode) {
    case AoaSelectionMode::kRssi:
      return "rssi";
    case AoaSelectionMode::kExternal:
      return "external";
    case AoaSelectionMode::kAllInFov:
      break;
  }
  return "all_in_fov";
}

bool inFieldOfView(const AoaCandidate& board, const Eigen::Vector3d& point) {
  const Eigen::Vector3d v = point - board.position;
  const double n = v.norm();
  if (n < 1e-9) {
    return false;
  }
  const Eigen::Vector3d boresight = board.rotation.col(0);
  return boresight.dot(v) / n >= std::cos(board.field_of_view);
}

AoaSelector::AoaSelector(std::size_t board_count, const AoaSelectorConfig& config)
    : config_(config), rssi_(board_count) {}

void AoaSelector::recordRssi(std::size_t board, double rssi) {
  if (board >= rssi_.size() || !std::isfinite(rssi)) {
    return;
  }
  auto& window = rssi_[board];
  window.push_back(rssi);
  while (window.size() > config_.rssi_window) {
    window.pop_front();
  }
}

double AoaSelector::meanRssi(std::size_t board) const {
  if (board >= rssi_.size() || rssi_[board].empty()) {
    return -std::numeric_limits<double>::infinity();
  }
  double sum = 0.0;
  for (double v : rssi_[board])
    sum += v;
  return sum / static_cast<double>(rssi_[board].size());
}

double AoaSelector::score(std::size_t board) const {
  if (board >= rssi_.size() || rssi_[board].empty()) {
    return -std::numeric_limits<double>::infinity();
  }
  const auto& w = rssi_[board];
  const double mean = meanRssi(board);
  double var = 0.0;
  for (double v : w)
    var += (v - mean) * (v - mean);
  var /= static_cast<double>(w.size());
  return mean - 2.0 * std::sqrt(var);
}

std::size_t AoaSelector::bestByScore(const std::vector<AoaCandidate>& fresh,
                                     const std::vector<std::size_t>& eligible) const {
  std::size_t best = eligible.front();
  for (std::size_t i : eligible) {
    if (score(fresh[i].board) > score(fresh[best].board)) {
      best = i;
    }
  }
  return best;
}

std::size_t AoaSelector::majorityVote(const std::vector<AoaCandidate>& fresh,
                                      const std::vector<std::size_t>& eligible, std::size_t best) {
  votes_.push_back(fresh[best].board);
  while (votes_.size() > config_.vote_window) {
    votes_.pop_front();
  }
  std::map<std::size_t, int> counts;
  for (std::size_t board : votes_)
    ++counts[board];
  std::size_t chosen = best;
  int chosen_votes = counts[fresh[best].board];
  for (std::size_t i : eligible) {
    const int v = counts[fresh[i].board];
    if (v > chosen_votes) {
      chosen = i;
      chosen_votes = v;
    }
  }
  return chosen;
}

std::vector<std::size_t> AoaSelector::select(const std::vector<AoaCandidate>& fresh,
                                             const std::optional<Eigen::Vector3d>& estimate) {
  std::vector<std::size_t> eligible;
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    if (!estimate || inFieldOfView(fresh[i], *estimate)) {
      eligible.push_back(i);
    }
  }
  if (eligible.empty()) {
    return {};
  }
  if (!estimate) {
    // Nothing to test the fields of view against: one board, the loudest on average, once
    // every reporting board has been heard often enough to compare. The mean, not the
    // thesis's mean - 2 std: the question here is which board faces the tag, and a board
    // with the tag behind it is only some 6 dB weaker while the boards' spreads differ by
    // up to 2-3 dB with the angle (Tables 3.2-3.7), so the spread penalty picked the back
    // board of the cube at start-up in the simulated outdoor loop (seeds 2 and 3).
    const std::size_t needed = std::min(kMinRssiToChoose, config_.rssi_window);
    for (std::size_t i : eligible) {
      const std::size_t heard = fresh[i].board < rssi_.size() ? rssi_[fresh[i].board].size() : 0;
      if (heard < needed) {
        return {};
      }
    }
    std::size_t loudest = eligible.front();
    for (std::size_t i : eligible) {
      if (meanRssi(fresh[i].board) > meanRssi(fresh[loudest].board)) {
        loudest = i;
      }
    }
    return {loudest};
  }
  switch (config_.mode) {
    case AoaSelectionMode::kRssi:
      return {majorityVote(fresh, eligible, bestByScore(fresh, eligible))};
    case AoaSelectionMode::kExternal: {
      std::size_t best = eligible.front();
      for (std::size_t i : eligible) {
        if (fresh[i].rssi > fresh[best].rssi)
          best = i;
      }
      return {best};
    }
    case AoaSelectionMode::kAllInFov:
      break;
  }
  return eligible;
}

}  // namespace estimation
}  // namespace radio_follow
