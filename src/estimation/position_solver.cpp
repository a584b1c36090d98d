// SPDX-License-Identifier: BSD-3-Clause
// The only translation unit of the locator that instantiates Ceres templates (slow to
// compile); everything else sees Ceres through position_solver.hpp's plain types.
#include "radio_follow/estimation/position_solver.hpp"

#include <ceres/ceres.h>
#include <ceres/covariance.h>

#include <cmath>
#include <deque>
#include <limits>
#include <tuple>
#include <type_traits>

#include "radio_follow/estimation/fisher.hpp"
#include "radio_follow/estimation/measurement_models.hpp"

namespace radio_follow {
namespace estimation {
namespace {

/// One deque of cost functions per kind of a solve's ObservationSet::lists().
template <typename Lists>
struct CostStorage;
template <typename... List>
struct CostStorage<std::tuple<const List&...>> {
  std::tuple<std::deque<typename List::value_type::Cost>...> deques;
};

std::unique_ptr<ceres::LossFunction> makeLoss(const LossConfig& loss) {
  switch (loss.type) {
    case LossType::kHuber:
      return std::make_unique<ceres::HuberLoss>(loss.scale);
    case LossType::kSoftL1:
      return std::make_unique<ceres::SoftLOneLoss>(loss.scale);
    case LossType::kCauchy:
      return std::make_unique<ceres::CauchyLoss>(loss.scale);
    case LossType::kNone:
      break;
  }
  return nullptr;
}

}  // namespace

struct PositionSolver::CeresParts {
  PerObservationKind<std::unique_ptr<ceres::LossFunction>> losses;
  ceres::HuberLoss convex_loss{2.0};
  ceres::SubsetManifold fixed_z{3, {2}};
  ceres::Problem::Options problem_options;
  ceres::Solver::Options solver_options;
};

PositionSolver::PositionSolver(const SolverConfig& config)
    : config_(config), parts_(std::make_unique<CeresParts>()) {
  for (std::size_t k = 0; k < config.losses.size(); ++k) {
    parts_->losses[k] = makeLoss(config.losses[k]);
  }
  // The solver owns nothing per problem: losses and the manifold live as long as the
  // solver, cost functions on the stack of solveOnce. No allocation churn per epoch.
  auto& po = parts_->problem_options;
  po.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  po.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  po.enable_fast_removal = false;
  auto& so = parts_->solver_options;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = config.max_iterations;
  so.num_threads = 1;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  so.function_tolerance = 1e-10;
  so.gradient_tolerance = 1e-12;
  so.parameter_tolerance = 1e-9;
}

PositionSolver::~PositionSolver() = default;

SolveResult PositionSolver::solve(const ObservationSet& observations,
                                  const Eigen::Vector3d& initial) const {
  return solveOnce(observations, initial, true, false);
}

SolveResult PositionSolver::solveCostOnly(const ObservationSet& observations,
                                          const Eigen::Vector3d& initial) const {
  return solveOnce(observations, initial, false, false);
}

SolveResult PositionSolver::solveCold(const ObservationSet& observations,
                                      const Eigen::Vector3d& initial) const {
  const SolveResult first = solveOnce(observations, initial, false, true);
  return solveOnce(observations, first.success ? first.position : initial, true, false);
}

SolveResult PositionSolver::solveMultiStart(const ObservationSet& observations,
                                            const std::vector<Eigen::Vector3d>& starts) const {
  SolveResult best;
  best.cost = std::numeric_limits<double>::infinity();
  for (const auto& start : starts) {
    SolveResult r = solveOnce(observations, start, false, true);
    if (r.success && r.cost < best.cost) {
      best = r;
    }
  }
  if (!best.success) {
    return best;
  }
  return solveOnce(observations, best.position, true, false);
}

SolveResult PositionSolver::solveOnce(const ObservationSet& observations,
                                      const Eigen::Vector3d& initial, bool with_covariance,
                                      bool convex_stage) const {
  SolveResult result;
  double p[3] = {initial.x(), initial.y(), config_.planar ? config_.height : initial.z()};
  // Cost functions are not movable; deques keep their addresses stable while growing.
  CostStorage<decltype(observations.lists())> costs;
  std::deque<RangeCost>& ranges = std::get<std::deque<RangeCost>>(costs.deques);

  ceres::Problem problem(parts_->problem_options);
  observations.forEach([&](const auto& list) {
    using Observation = typename std::decay_t<decltype(list)>::value_type;
    using Cost = typename Observation::Cost;
    ceres::LossFunction* loss =
        convex_stage ? &parts_->convex_loss : parts_->losses[kindIndex<Observation>()].get();
    auto& deque = std::get<std::deque<Cost>>(costs.deques);
    for (const auto& z : list) {
      deque.emplace_back(z);
      problem.AddResidualBlock(&deque.back(), loss, p);
    }
  });
  if (observations.ranges.empty()) {
    RangeObservation prior;
    prior.range = config_.prior_range;
    prior.sigma = config_.prior_range_sigma;
    ranges.emplace_back(prior);
    problem.AddResidualBlock(&ranges.back(), nullptr, p);
  }
  if (problem.NumResidualBlocks() == 0) {
    return result;
  }
  if (config_.planar) {
    problem.SetManifold(p, &parts_->fixed_z);
  }

  ceres::Solver::Summary summary;
  ceres::Solve(parts_->solver_options, &problem, &summary);
  result.position = Eigen::Vector3d(p[0], p[1], p[2]);
  result.cost = summary.final_cost;
  result.iterations = static_cast<int>(summary.iterations.size());
  result.success = summary.termination_type != ceres::FAILURE &&
                   summary.termination_type != ceres::USER_FAILURE &&
                   std::isfinite(summary.final_cost) && result.position.allFinite();
  if (!result.success || !with_covariance) {
    return result;
  }
  if (config_.ceres_covariance) {
    ceres::Covariance::Options co;
    co.algorithm_type = ceres::DENSE_SVD;
    co.null_space_rank = -1;  // drop (and so report) every direction below the threshold
    co.min_reciprocal_condition_number = 1e-10;
    ceres::Covariance covariance(co);
    std::vector<std::pair<const double*, const double*>> blocks{{p, p}};
    if (covariance.Compute(blocks, &problem)) {
      Eigen::Matrix<double, 3, 3, Eigen::RowMajor> c;
      covariance.GetCovarianceBlock(p, p, c.data());
      const Eigen::Matrix3d fisher = fisherInformation(observations, result.position);
      const int dims = config_.planar ? 2 : 3;
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(fisher);
      // DENSE_SVD with null_space_rank = -1 silently zeroes unobservable directions;
      // a zero variance there would claim certainty, so reject rank-deficient problems.
      const bool full_rank = dims == 2 ? positionCrlb(fisher, true).has_value()
                                       : eig.eigenvalues()(0) > 1e-10 * eig.eigenvalues()(2);
      if (full_rank && c.allFinite()) {
        result.covariance = c;
        result.covariance_valid = true;
      }
    }
    return result;
  }
  computeCovariance(observations, result);
  return result;
}

void PositionSolver::computeCovariance(const ObservationSet& observations,
                                       SolveResult& result) const {
  Eigen::Matrix3d info = fisherInformation(observations, result.position);
  if (observations.ranges.empty()) {
    ObservationSet prior;
    RangeObservation z;
    z.range = config_.prior_range;
    z.sigma = config_.prior_range_sigma;
    prior.ranges.push_back(z);
    info += fisherInformation(prior, result.position);
  }
  const auto covariance = positionCrlb(info, config_.planar);
  if (covariance) {
    result.covariance = *covariance;
    result.covariance_valid = true;
  }
}

}  // namespace estimation
}  // namespace radio_follow
