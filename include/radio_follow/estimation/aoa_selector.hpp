// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace radio_follow {
namespace estimation {

enum class AoaSelectionMode {
  /// Thesis Listing 4.1: per board the last N RSSI values, score = mean - 2 std, the best
  /// score wins, and the board chosen most often in the last few selections is used.
  kRssi,
  /// Thesis "external": the board whose field of view contains the current estimate;
  /// among several, the highest RSSI.
  kExternal,
  /// Every board whose field of view contains the current estimate, each as its own
  /// residual (more information, and no switching transients).
  kAllInFov,
};

/// "rssi" | "external" | "all_in_fov"; throws ParamError naming `parameter` otherwise.
AoaSelectionMode parseAoaSelectionMode(const std::string& text, const std::string& parameter);
std::string toString(AoaSelectionMode mode);

struct AoaSelectorConfig {
  AoaSelectionMode mode = AoaSelectionMode::kAllInFov;
  /// RSSI values kept per board (thesis N).
  std::size_t rssi_window = 10;
  /// Selections the majority vote of the rssi mode runs over.
  std::size_t vote_window = 5;
};

/// Without an estimate, boards are compared by RSSI only once every board with a fresh
/// bearing has this many RSSI values (or rssi_window, if smaller).
constexpr std::size_t kMinRssiToChoose = 10;

/// One board with a fresh bearing.
struct AoaCandidate {
  std::size_t board = 0;  ///< board index in the layout
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< board -> fixed frame
  double field_of_view = 1.22;                             ///< half-angle, rad
  double rssi = -100.0;                                    ///< of the fresh bearing, dBm
};

/// True when `point` lies within the board's field-of-view cone around its boresight.
bool inFieldOfView(const AoaCandidate& board, const Eigen::Vector3d& point);

/// Chooses which fresh bearings the solver may use.
///
/// A board with the tag behind it still reports a bearing inside its own field of view
/// (plausible garbage), so whenever an estimate exists every mode drops the boards whose
/// field of view does not contain it. Without an estimate the highest mean RSSI decides
/// (the strongest signal is the board facing the tag), and only one board is used, once
/// every reporting board has kMinRssiToChoose RSSI values: the first board to report is not
/// the one facing the tag more often than chance, and a wrong first choice keeps itself
/// (later estimates only admit the boards facing it).
class AoaSelector {
 public:
  AoaSelector(std::size_t board_count, const AoaSelectorConfig& config);

  /// Records the RSSI of every received bearing (also those not selected).
  void recordRssi(std::size_t board, double rssi);

  /// Indices into `fresh` of the bearings to use; empty when none qualifies.
  std::vector<std::size_t> select(const std::vector<AoaCandidate>& fresh,
                                  const std::optional<Eigen::Vector3d>& estimate);

  /// Mean of the board's recent RSSI, dBm; -inf without values.
  double meanRssi(std::size_t board) const;
  /// Thesis score mean - 2 std of the board's recent RSSI; -inf without values.
  double score(std::size_t board) const;
  /// Forgets the vote history (target lost).
  void reset() { votes_.clear(); }

 private:
  std::size_t bestByScore(const std::vector<AoaCandidate>& fresh,
                          const std::vector<std::size_t>& eligible) const;
  std::size_t majorityVote(const std::vector<AoaCandidate>& fresh,
                           const std::vector<std::size_t>& eligible, std::size_t best);

  AoaSelectorConfig config_;
  std::vector<std::deque<double>> rssi_;
  std::deque<std::size_t> votes_;
};

}  // namespace estimation
}  // namespace radio_follow
