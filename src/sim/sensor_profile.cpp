// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/sim/sensor_profile.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace sim {
namespace {

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

bool chance(double probability, Rng& rng) {
  return probability > 0.0 && uniform(rng, 0.0, 1.0) < probability;
}

/// splitmix64's finaliser: neighbouring seeds give unrelated generator states.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// The generator of one device's constant errors: a function of the robot's hardware seed
/// and the device's ID only, so neither the noise seed nor the order of the layout's
/// entries moves them.
Rng hardwareRng(std::uint64_t hardware_seed, const std::string& id) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a
  for (const char c : id) {
    hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  }
  return Rng(mix(mix(hardware_seed) ^ hash));
}

}  // namespace

SensorProfile parseSensorProfile(const std::string& text, const std::string& name) {
  require(text == "ideal" || text == "realistic", name, text, "'realistic' or 'ideal'");
  return text == "ideal" ? SensorProfile::kIdeal : SensorProfile::kRealistic;
}

std::string toString(SensorProfile profile) {
  return profile == SensorProfile::kIdeal ? "ideal" : "realistic";
}

double GaussMarkov::sample(double t, Rng& rng) {
  if (sigma_ <= 0.0) {
    return 0.0;
  }
  std::normal_distribution<double> unit(0.0, 1.0);
  if (!last_t_) {
    value_ = sigma_ * unit(rng);
  } else {
    const double a = std::exp(-std::max(0.0, t - *last_t_) / tau_);
    value_ = a * value_ + std::sqrt(1.0 - a * a) * sigma_ * unit(rng);
  }
  last_t_ = t;
  return value_;
}

TwrHardware drawTwrHardware(std::uint64_t hardware_seed, const std::string& module_id,
                            const std::string& tag_id, const RealisticFigures& f) {
  Rng rng = hardwareRng(hardware_seed, "twr:" + module_id + "/" + tag_id);
  TwrHardware h;
  h.bias = uniform(rng, f.twr_bias_min, f.twr_bias_max);
  h.scale = uniform(rng, f.twr_scale_min, f.twr_scale_max);
  h.direction = f.twr_direction_amplitude;
  h.phase = uniform(rng, -kPi, kPi);
  return h;
}

TwrNoiseState::TwrNoiseState(const RealisticFigures& f, double sigma_scale)
    : figures_(f),
      slow_(sigma_scale * f.twr_sigma * std::sqrt(f.twr_slow_share), f.twr_slow_tau),
      fast_(sigma_scale * f.twr_sigma * std::sqrt(1.0 - f.twr_slow_share), f.twr_fast_tau) {}

double TwrNoiseState::noise(double t, Rng& rng) {
  return slow_.sample(t, rng) + fast_.sample(t, rng);
}

double TwrNoiseState::outlier(Rng& rng) {
  if (burst_left_ > 0) {
    --burst_left_;
    return burst_excess_;
  }
  if (!chance(figures_.twr_outlier_start, rng)) {
    return 0.0;
  }
  // A reflection off a wall or the ground: the longer path, the same for a few epochs
  // while the geometry barely changes. Rarely the first-path detection fires early.
  const double excess =
      std::exponential_distribution<double>(1.0 / figures_.twr_outlier_mean_excess)(rng);
  burst_excess_ = std::min(figures_.twr_outlier_max, figures_.twr_outlier_min + excess);
  if (chance(figures_.twr_outlier_short_share, rng)) {
    burst_excess_ = -figures_.twr_outlier_min;
  }
  while (chance(figures_.twr_outlier_continue, rng)) {
    ++burst_left_;
  }
  return burst_excess_;
}

std::optional<double> simulateRealisticTwr(const TwrModule& module, const TwrHardware& hardware,
                                           const TwrNoise& noise, TwrNoiseState& state,
                                           const Eigen::Vector3d& target, double t, Rng& rng) {
  // The correlated noise runs on through a dropout: the channel does not wait for a reply.
  const double correlated = state.noise(t, rng);
  if (chance(noise.dropout_probability, rng) || chance(state.figures().twr_dropout, rng)) {
    return std::nullopt;
  }
  const Eigen::Vector3d offset = target - module.position;
  const double distance = offset.norm();
  const double bearing = std::atan2(offset.y(), offset.x());
  double range = distance + hardware.bias + hardware.scale * distance +
                 hardware.direction * std::cos(bearing - hardware.phase) + correlated +
                 state.outlier(rng);
  for (const auto& sector : noise.occlusions) {
    const bool applies = sector.module.empty() || sector.module == module.id;
    if (applies && sector.contains(bearing) && chance(sector.reflection_probability, rng)) {
      range += sector.reflection_extra;
    }
  }
  return std::max(0.0, range);
}

AoaBoard mountedAoaBoard(const AoaBoard& board, std::uint64_t hardware_seed,
                         const RealisticFigures& f) {
  Rng rng = hardwareRng(hardware_seed, "aoa:" + board.id);
  AoaBoard mounted = board;
  const double yaw = uniform(rng, -f.aoa_yaw_error_max, f.aoa_yaw_error_max);
  mounted.orientation = board.orientation * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
  return mounted;
}

AoaErrorState::AoaErrorState(const AoaBoard& board, std::uint64_t hardware_seed,
                             const RealisticFigures& f)
    : figures_(f),
      mounted_(mountedAoaBoard(board, hardware_seed, f)),
      // Correlation along s = t / slow_time + path / slow_length: a unit time constant.
      slow_azimuth_(f.aoa_slow_sigma, 1.0),
      slow_elevation_(f.aoa_slow_sigma, 1.0) {
  Rng rng = hardwareRng(hardware_seed, "aoa-bias:" + board.id);
  azimuth_bias_ = std::normal_distribution<double>(0.0, f.aoa_bias_sigma)(rng);
  elevation_bias_ = uniform(rng, f.aoa_elevation_bias_min, f.aoa_elevation_bias_max);
}

std::optional<AoaSample> AoaErrorState::simulate(const AoaNoise& noise,
                                                 const Eigen::Vector3d& target, double t,
                                                 Rng& rng) {
  std::optional<AoaSample> sample = simulateAoa(mounted_, noise, target, rng);
  if (!sample) {
    return sample;
  }
  const RealisticFigures& f = figures_;
  const Eigen::Vector3d local = mounted_.orientation.conjugate() * (target - mounted_.position);
  if (last_local_) {
    path_ += (local - *last_local_).norm();
  }
  last_local_ = local;
  const double s = t / f.aoa_slow_time + path_ / f.aoa_slow_length;
  std::student_t_distribution<double> tail(f.aoa_event_dof);
  const double scale = noise.sigma_scale;
  sample->azimuth += azimuth_bias_ + scale * (slow_azimuth_.sample(s, rng) +
                                              f.aoa_event_scale * tail(rng));
  sample->elevation += elevation_bias_ + scale * (slow_elevation_.sample(s, rng) +
                                                  f.aoa_event_scale * tail(rng));
  if (chance(f.aoa_reflection, rng)) {
    // The strongest path came off a wall: a plausible angle, nowhere near the tag.
    sample->azimuth = uniform(rng, -kPi / 2.0, kPi / 2.0);
  }
  if (chance(f.aoa_shadow, rng)) {
    // The wearer's body between tag and board: what arrives comes over it, from above.
    sample->elevation += uniform(rng, deg2rad(5.0), f.aoa_shadow_max);
  }
  // The board reports both angles in [-90, 90] deg (simulateAoa).
  sample->azimuth = std::clamp(sample->azimuth, -kPi / 2.0, kPi / 2.0);
  sample->elevation = std::clamp(sample->elevation, -kPi / 2.0, kPi / 2.0);
  return sample;
}

TdoaHardware::TdoaHardware(const std::vector<TdoaAnchor>& anchors, std::uint64_t hardware_seed,
                           const RealisticFigures& f)
    : figures_(f) {
  for (const TdoaAnchor& anchor : anchors) {
    Rng rng = hardwareRng(hardware_seed, "tdoa:" + anchor.id);
    offsets_.push_back(uniform(rng, -f.tdoa_offset_max, f.tdoa_offset_max));
    drift_.emplace_back(f.tdoa_slow_sigma, f.tdoa_slow_tau);
  }
}

std::vector<double> simulateBlink(std::optional<TdoaHardware>& hardware,
                                  const std::vector<TdoaAnchor>& anchors, std::size_t reference,
                                  double sigma, const Eigen::Vector3d& target, double t, Rng& rng) {
  return hardware ? hardware->simulate(anchors, reference, sigma, target, t, rng)
                  : simulateTdoa(anchors, reference, sigma, target, rng);
}

std::vector<double> TdoaHardware::simulate(const std::vector<TdoaAnchor>& anchors,
                                           std::size_t reference, double sigma,
                                           const Eigen::Vector3d& target, double t, Rng& rng) {
  std::vector<double> differences = simulateTdoa(anchors, reference, sigma, target, rng);
  if (differences.empty()) {
    return differences;
  }
  const RealisticFigures& f = figures_;
  // A reflection lasts 1 / (1 - continue) TWR epochs on average: that share of blinks.
  const double outlier = f.twr_outlier_start / (1.0 - f.twr_outlier_continue);
  std::vector<double> error(anchors.size());
  for (std::size_t i = 0; i < anchors.size(); ++i) {
    error[i] = offsets_[i] + drift_[i].sample(t, rng);
    if (chance(outlier, rng)) {
      const double excess =
          std::exponential_distribution<double>(1.0 / f.twr_outlier_mean_excess)(rng);
      error[i] += std::min(f.twr_outlier_max, f.twr_outlier_min + excess);
    }
  }
  if (chance(f.twr_dropout, rng)) {
    return {};  // the reference (or too many anchors) missed it: the driver drops it
  }
  std::size_t k = 0;
  for (std::size_t i = 0; i < anchors.size(); ++i) {
    if (i != reference) {
      differences[k++] += error[i] - error[reference];
    }
  }
  return differences;
}

}  // namespace sim
}  // namespace radio_follow
