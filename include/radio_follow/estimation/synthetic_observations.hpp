// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <random>

#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/measurement_models.hpp"

namespace radio_follow {
namespace estimation {

/// Noise levels of synthetic measurements (Monte Carlo, benchmarks, tests).
struct SyntheticNoise {
  double range_sigma = 0.03;       ///< m
  double azimuth_sigma = 0.035;    ///< rad
  double elevation_sigma = 0.035;  ///< rad
  bool use_elevation = true;
};

/// Noise-free observations of a target at p from a layout: a range from every TWR module
/// and the bearing of up to `max_bearings` boards whose field of view contains p, the
/// best-aligned first (what an ideal board selection would pick). Sigmas set from `noise`.
ObservationSet idealObservations(const Layout& layout, const Eigen::Vector3d& p,
                                 const SyntheticNoise& noise, int max_bearings);

/// Adds zero-mean Gaussian noise with each observation's own sigma.
void addGaussianNoise(ObservationSet& observations, std::mt19937_64& rng);

}  // namespace estimation
}  // namespace radio_follow
