// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/estimation/initializer.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {
namespace estimation {
namespace {

// A linear system whose normal matrix has a reciprocal condition number below this is
// treated as degenerate (modules on a line / plane): its solution would be noise.
constexpr double kMinRcond = 1e-8;

template <int N>
std::optional<Eigen::Matrix<double, N, 1>> solveNormal(const Eigen::MatrixXd& a,
                                                       const Eigen::VectorXd& b) {
  const Eigen::Matrix<double, N, N> normal = a.transpose() * a;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eig(normal);
  const auto ev = eig.eigenvalues();
  if (!(ev(N - 1) > 0.0) || ev(0) < kMinRcond * ev(N - 1)) {
    return std::nullopt;
  }
  return Eigen::Matrix<double, N, 1>(normal.ldlt().solve(a.transpose() * b));
}

/// R x = Q^T b (seed 002 eqs 6-8). Column pivoting makes R's diagonal reveal the rank:
/// the same degeneracy threshold as solveNormal's, on A rather than on A^T A.
std::optional<Eigen::VectorXd> solveQr(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  const Eigen::MatrixXd& r = qr.matrixQR();
  const double largest = std::abs(r(0, 0));
  const double smallest = std::abs(r(a.cols() - 1, a.cols() - 1));
  if (!(largest > 0.0) || smallest < std::sqrt(kMinRcond) * largest) {
    return std::nullopt;
  }
  return Eigen::VectorXd(qr.solve(b));
}

/// The linear system of the squared-range equations, each minus the first (`consecutive`
/// false) or minus the next (true, seed 002 eq 5). Rows: 2 (m_j - m_i)^T p =
/// d_i - d_j + |m_j|^2 - |m_i|^2 for the pair (i, j).
struct LinearSystem {
  Eigen::MatrixXd a;
  Eigen::VectorXd b;
};
std::optional<LinearSystem> linearSystem(const std::vector<RangeObservation>& ranges,
                                         const InitializerConfig& config, bool consecutive) {
  const int dims = config.planar ? 2 : 3;
  const int n = static_cast<int>(ranges.size());
  if (n < dims + 1) {
    return std::nullopt;
  }
  // Squared horizontal distance in 2D (the height difference is known), squared range in 3D.
  auto squared = [&](const RangeObservation& z) {
    double d2 = z.range * z.range;
    if (config.planar) {
      const double dz = config.height - z.module.z();
      d2 = std::max(0.0, d2 - dz * dz);
    }
    return d2;
  };
  LinearSystem system{Eigen::MatrixXd(n - 1, dims), Eigen::VectorXd(n - 1)};
  for (int j = 1; j < n; ++j) {
    const RangeObservation& zi = ranges[consecutive ? j - 1 : 0];
    const Eigen::Vector3d& mi = zi.module;
    const Eigen::Vector3d& mj = ranges[j].module;
    system.a.row(j - 1) = 2.0 * (mj - mi).head(dims).transpose();
    system.b(j - 1) = squared(zi) - squared(ranges[j]) + mj.head(dims).squaredNorm() -
                      mi.head(dims).squaredNorm();
  }
  return system;
}

Eigen::Vector3d toPosition(const Eigen::VectorXd& p, const InitializerConfig& config) {
  Eigen::Vector3d position(p(0), p(1), config.height);
  if (!config.planar) {
    position.z() = p(2);
  }
  return position;
}

}  // namespace

std::optional<Eigen::Vector3d> trilaterate(const std::vector<RangeObservation>& ranges,
                                           const InitializerConfig& config) {
  const auto system = linearSystem(ranges, config, false);
  if (!system) {
    return std::nullopt;
  }
  if (config.planar) {
    const auto xy = solveNormal<2>(system->a, system->b);
    if (!xy) {
      return std::nullopt;
    }
    return Eigen::Vector3d(xy->x(), xy->y(), config.height);
  }
  const auto p = solveNormal<3>(system->a, system->b);
  if (!p) {
    return std::nullopt;
  }
  return *p;
}

std::optional<Eigen::Vector3d> trilaterateQr(const std::vector<RangeObservation>& ranges,
                                             const InitializerConfig& config) {
  const auto system = linearSystem(ranges, config, true);
  if (!system) {
    return std::nullopt;
  }
  const auto p = solveQr(system->a, system->b);
  return p ? std::optional<Eigen::Vector3d>(toPosition(*p, config)) : std::nullopt;
}

Eigen::Vector3d bearingDirection(const BearingObservation& bearing) {
  const double ce = std::cos(bearing.use_elevation ? bearing.elevation : 0.0);
  const Eigen::Vector3d local(ce * std::cos(bearing.azimuth), ce * std::sin(bearing.azimuth),
                              std::sin(bearing.use_elevation ? bearing.elevation : 0.0));
  return bearing.rotation * local;
}

std::vector<Eigen::Vector3d> multiStartCandidates(const ObservationSet& observations,
                                                  const InitializerConfig& config) {
  std::vector<Eigen::Vector3d> candidates;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = config.default_range;
  if (!observations.ranges.empty()) {
    const RangeObservation& z = observations.ranges.front();
    centre = z.module;
    radius = z.range;
  }
  // Along each bearing first: it is the most likely start and wins ties in cost.
  for (const auto& bearing : observations.bearings) {
    Eigen::Vector3d dir = bearingDirection(bearing);
    if (config.planar) {
      dir.z() = 0.0;
      if (dir.norm() < 1e-6) {
        continue;
      }
      dir.normalize();
    }
    // Horizontal distance from the board at which the range circle is met (approximately:
    // the board is close to the ranging module on every layout).
    double along = radius;
    if (config.planar && !observations.ranges.empty()) {
      const double dz = config.height - centre.z();
      along = std::sqrt(std::max(0.0, radius * radius - dz * dz));
    }
    Eigen::Vector3d p = bearing.board + along * dir;
    if (config.planar) {
      p.z() = config.height;
    }
    candidates.push_back(p);
  }
  double horizontal = radius;
  if (config.planar) {
    const double dz = config.height - centre.z();
    horizontal = std::sqrt(std::max(1e-4, radius * radius - dz * dz));
  }
  for (int k = 0; k < config.circle_points; ++k) {
    const double angle = 2.0 * kPi * k / config.circle_points;
    Eigen::Vector3d p =
        centre + horizontal * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
    p.z() = config.planar ? config.height : centre.z();
    candidates.push_back(p);
  }
  return candidates;
}

}  // namespace estimation
}  // namespace radio_follow
