// SPDX-License-Identifier: BSD-3-Clause
// The thesis's fused position solve (seed 003, eqs 4.15-4.16, as its reference
// implementation ctu-vras/follow_me `radio_locator.py` builds it), re-implemented with
// the same Ceres machinery as radio_follow's PositionSolver so that the two differ only in
// the formulation. It is the baseline the locator is measured against:
// bench_locator_solve (time per solve) and bench_thesis_accuracy (RMSE against the
// Cramer-Rao bound). Not part of the core: nothing runs it but the benchmarks.
//
// The formulation, row by row, all with SciPy's `soft_l1` loss at f_scale 1:
// - a TWR range: |p - t_i|^2 - r_i^2 (squared distances, no sigma: far modules weigh more);
// - a bearing: 3 |azimuth error| in radians (the elevation is not used, no sigma);
// - the target height is fixed (the thesis's 2D mode): x and y are the unknowns.
#pragma once

#include <ceres/ceres.h>

#include <Eigen/Core>
#include <cmath>
#include <deque>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/estimation/measurement_models.hpp"

namespace thesis_baseline {

/// |p - t|^2 - r^2 with p = (x, y, height).
class SquaredRangeCost : public ceres::SizedCostFunction<1, 2> {
 public:
  SquaredRangeCost(const Eigen::Vector3d& module, double range, double height)
      : module_(module), range_(range), height_(height) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Vector3d d(parameters[0][0] - module_.x(), parameters[0][1] - module_.y(),
                            height_ - module_.z());
    residuals[0] = d.squaredNorm() - range_ * range_;
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      jacobians[0][0] = 2.0 * d.x();
      jacobians[0][1] = 2.0 * d.y();
    }
    return true;
  }

 private:
  Eigen::Vector3d module_;
  double range_;
  double height_;
};

/// 3 |azimuth(p) - measured azimuth| in the board's frame, radians.
class AbsAzimuthCost : public ceres::SizedCostFunction<1, 2> {
 public:
  AbsAzimuthCost(const radio_follow::estimation::BearingObservation& z, double height)
      : z_(z), height_(height) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Vector3d p(parameters[0][0], parameters[0][1], height_);
    const Eigen::Vector3d v = z_.rotation.transpose() * (p - z_.board);
    const double error = radio_follow::wrapAngleFast(std::atan2(v.y(), v.x()) - z_.azimuth);
    residuals[0] = kWeight * std::abs(error);
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      const double rho2 = v.x() * v.x() + v.y() * v.y();
      Eigen::RowVector3d d_azimuth = Eigen::RowVector3d::Zero();
      if (rho2 > 1e-18) {
        d_azimuth << -v.y() / rho2, v.x() / rho2, 0.0;
      }
      const Eigen::RowVector3d row =
          kWeight * (error < 0.0 ? -1.0 : 1.0) * d_azimuth * z_.rotation.transpose();
      jacobians[0][0] = row(0);
      jacobians[0][1] = row(1);
    }
    return true;
  }

 private:
  static constexpr double kWeight = 3.0;  // radio_locator.py: 3.0 * abs(angle)
  radio_follow::estimation::BearingObservation z_;
  double height_;
};

struct ThesisResult {
  bool success = false;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

/// Solves the thesis's problem from a start (the last estimate, as the thesis does).
/// Solver options are PositionSolver's: dense QR, Levenberg-Marquardt, 25 iterations, the
/// same tolerances.
class ThesisSolver {
 public:
  explicit ThesisSolver(double height) : height_(height) {
    problem_options_.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    problem_options_.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    problem_options_.enable_fast_removal = false;
    options_.linear_solver_type = ceres::DENSE_QR;
    options_.max_num_iterations = 25;
    options_.num_threads = 1;
    options_.logging_type = ceres::SILENT;
    options_.minimizer_progress_to_stdout = false;
    options_.function_tolerance = 1e-10;
    options_.gradient_tolerance = 1e-12;
    options_.parameter_tolerance = 1e-9;
  }

  ThesisResult solve(const radio_follow::estimation::ObservationSet& observations,
                     const Eigen::Vector3d& initial) const {
    double xy[2] = {initial.x(), initial.y()};
    std::deque<SquaredRangeCost> ranges;
    std::deque<AbsAzimuthCost> bearings;
    ceres::Problem problem(problem_options_);
    for (const auto& z : observations.ranges) {
      ranges.emplace_back(z.module, z.range, height_);
      problem.AddResidualBlock(&ranges.back(), &loss_, xy);
    }
    for (const auto& z : observations.bearings) {
      bearings.emplace_back(z, height_);
      problem.AddResidualBlock(&bearings.back(), &loss_, xy);
    }
    ThesisResult result;
    if (problem.NumResidualBlocks() == 0) {
      return result;
    }
    ceres::Solver::Summary summary;
    ceres::Solve(options_, &problem, &summary);
    result.position = Eigen::Vector3d(xy[0], xy[1], height_);
    result.success = summary.termination_type != ceres::FAILURE &&
                     std::isfinite(summary.final_cost) && result.position.allFinite();
    return result;
  }

 private:
  double height_;
  mutable ceres::SoftLOneLoss loss_{1.0};  // SciPy least_squares(loss="soft_l1"), f_scale 1
  ceres::Problem::Options problem_options_;
  ceres::Solver::Options options_;
};

}  // namespace thesis_baseline
