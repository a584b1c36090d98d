// SPDX-License-Identifier: BSD-3-Clause
// The C++ half of issue 14's side-by-side latency comparison with the thesis's SciPy solve
// (bench/thesis_scipy.py runs this program, then SciPy on the epochs it wrote, and prints
// the ratios). A person walks around a standing robot (1.2 m/s, 2-9 m away); every 0.1 s
// each TWR module ranges once and each AoA board whose field of view contains the person
// reports a bearing, each at its own stamp. The same epochs go to:
// - Locator::update with the shipped config/locator.yaml (the particle estimator), and with
//   `estimator: solver` (Ceres solve + Kalman filter): the node's whole update;
// - PositionSolver::solve alone, warm-started at the previous epoch's position;
// - the thesis's formulation in Ceres (thesis_solver.hpp) from the same starts.
// Writes the epochs (layout geometry, measurements, starts) to EPOCHS.csv and one line of
// per-call latencies per case and estimator (median, p99, mean, us) to stdout, CSV.
//
//   "$RF_WS"/devel/lib/radio_follow/bench_scipy_baseline EPOCHS.csv [--passes N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/yaml_params.hpp"
#include "radio_follow/config/layout.hpp"
#include "radio_follow/estimation/locator.hpp"
#include "radio_follow/estimation/measurement_models.hpp"
#include "radio_follow/estimation/position_solver.hpp"
#include "thesis_solver.hpp"

namespace rf = radio_follow;
namespace est = radio_follow::estimation;

namespace {

constexpr double kHeight = 1.0;        // the person's tag plane (2D mode), m
constexpr double kPeriod = 0.1;        // every sensor's report period, s
constexpr double kSensorStep = 0.002;  // stagger between the sensors' stamps, s
constexpr double kSpeed = 1.2;         // walking speed, m/s
constexpr int kEpochs = 600;
// The first epochs of every pass are a cold start (multi-start solve, track
// confirmation): left out of every estimator's statistics alike.
constexpr int kWarmUp = 20;
constexpr double kRangeSigma = 0.03;              // m
constexpr double kAngleSigma = rf::deg2rad(5.0);  // rad, azimuth and elevation

struct Bearing {
  std::size_t board = 0;  // index into the layout's boards
  est::BearingObservation z;
};

struct Epoch {
  double t = 0.0;  // stamp of the first measurement, s
  est::ObservationSet obs;
  std::vector<Bearing> bearings;                    // the same bearings, with their boards
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // warm start of the solves
};

/// The walk: distance 5.5 + 3.5 sin(0.11 t) m, walking at kSpeed around the robot.
std::vector<Epoch> walk(const rf::Layout& layout, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Epoch> epochs;
  double angle = 0.3;
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  for (int k = 0; k < kEpochs; ++k) {
    const double t = k * kPeriod;
    const double r = 5.5 + 3.5 * std::sin(0.11 * t);
    const double dr = 3.5 * 0.11 * std::cos(0.11 * t);
    angle += std::sqrt(std::max(0.0, kSpeed * kSpeed - dr * dr)) / r * kPeriod;
    const Eigen::Vector3d p(r * std::cos(angle), r * std::sin(angle), kHeight);
    Epoch e;
    e.t = t;
    for (const auto& m : layout.twr_modules) {
      est::RangeObservation z;
      z.module = m.position;
      z.range = (p - m.position).norm() + kRangeSigma * normal(rng);
      z.sigma = kRangeSigma;
      e.obs.ranges.push_back(z);
    }
    for (std::size_t b = 0; b < layout.aoa_boards.size(); ++b) {
      const rf::AoaBoard& board = layout.aoa_boards[b];
      const Eigen::Matrix3d rotation = board.orientation.toRotationMatrix();
      const Eigen::Vector3d v = (p - board.position).normalized();
      if (std::acos(std::clamp(rotation.col(0).dot(v), -1.0, 1.0)) > board.field_of_view) {
        continue;  // all_in_fov: only boards that see the person
      }
      Bearing bearing{b, {}};
      bearing.z.board = board.position;
      bearing.z.rotation = rotation;
      const Eigen::Vector2d ae = est::predictBearing(p, board.position, rotation);
      bearing.z.azimuth = rf::wrapAngleFast(ae(0) + kAngleSigma * normal(rng));
      bearing.z.elevation = ae(1) + kAngleSigma * normal(rng);
      bearing.z.sigma_azimuth = bearing.z.sigma_elevation = kAngleSigma;
      e.obs.bearings.push_back(bearing.z);
      e.bearings.push_back(bearing);
    }
    // As in tracking: the last position, 5 cm off.
    e.start = k == 0 ? p : previous;
    e.start += Eigen::Vector3d(0.05 * normal(rng), 0.05 * normal(rng), 0.0);
    e.start.z() = kHeight;
    previous = p;
    epochs.push_back(e);
  }
  return epochs;
}

void writeEpochs(std::ofstream& out, const std::string& name, const std::vector<Epoch>& epochs) {
  out.precision(17);
  for (std::size_t k = 0; k < epochs.size(); ++k) {
    const Epoch& e = epochs[k];
    out << "start," << name << ',' << k << ',' << e.start.x() << ',' << e.start.y() << ','
        << kHeight << '\n';
    for (const auto& z : e.obs.ranges) {
      out << "range," << name << ',' << k << ',' << z.module.x() << ',' << z.module.y() << ','
          << z.module.z() << ',' << z.range << '\n';
    }
    for (const auto& z : e.obs.bearings) {
      out << "bearing," << name << ',' << k << ',' << z.board.x() << ',' << z.board.y() << ','
          << z.board.z() << ',' << z.azimuth;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
          out << ',' << z.rotation(r, c);
        }
      }
      out << '\n';
    }
  }
}

class Timer {
 public:
  void start() { start_ = std::chrono::steady_clock::now(); }
  void stop(bool keep) {
    const auto end = std::chrono::steady_clock::now();
    if (keep) {
      micros_.push_back(std::chrono::duration<double, std::micro>(end - start_).count());
    }
  }
  void print(const std::string& name, const std::string& estimator) {
    std::sort(micros_.begin(), micros_.end());
    double sum = 0.0;
    for (const double m : micros_) {
      sum += m;
    }
    const std::size_t n = micros_.size();
    std::printf("%s,%s,%zu,%.2f,%.2f,%.2f\n", name.c_str(), estimator.c_str(), n, micros_[n / 2],
                micros_[static_cast<std::size_t>(0.99 * static_cast<double>(n - 1))],
                sum / static_cast<double>(n));
  }

 private:
  std::chrono::steady_clock::time_point start_;
  std::vector<double> micros_;
};

/// The node's whole update per epoch: every measurement added at its stamp, then update().
void timeLocator(const rf::Layout& layout, const est::LocatorConfig& config,
                 const std::vector<Epoch>& epochs, int passes, Timer& timer) {
  for (int pass = 0; pass < passes; ++pass) {
    est::Locator locator(layout, config);
    for (std::size_t k = 0; k < epochs.size(); ++k) {
      const Epoch& e = epochs[k];
      double t = e.t;
      for (std::size_t m = 0; m < e.obs.ranges.size(); ++m) {
        locator.addRange(m, e.obs.ranges[m].range, t);
        t += kSensorStep;
      }
      for (const auto& b : e.bearings) {
        locator.addBearing(b.board, b.z.azimuth, b.z.elevation, -60.0, t);
        t += kSensorStep;
      }
      timer.start();
      const est::LocatorEstimate estimate = locator.update(t);
      timer.stop(k >= static_cast<std::size_t>(kWarmUp));
      if (!std::isfinite(estimate.position.x())) {
        std::fprintf(stderr, "bench_scipy_baseline: non-finite estimate\n");
      }
    }
  }
}

template <typename Solve>
void timeSolves(const std::vector<Epoch>& epochs, int passes, Timer& timer, Solve solve) {
  for (int pass = 0; pass < passes; ++pass) {
    for (std::size_t k = 0; k < epochs.size(); ++k) {
      timer.start();
      const bool ok = solve(epochs[k]);
      timer.stop(k >= static_cast<std::size_t>(kWarmUp));
      if (!ok) {
        std::fprintf(stderr, "bench_scipy_baseline: a solve failed\n");
      }
    }
  }
}

int usage(const char* problem) {
  std::fprintf(stderr,
               "bench_scipy_baseline: %s\nusage: bench_scipy_baseline EPOCHS.csv [--passes N]\n",
               problem);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 4) {
    return usage("wrong arguments");
  }
  int passes = 5;
  if (argc == 4) {
    if (std::string(argv[2]) != "--passes" || (passes = std::atoi(argv[3])) < 1) {
      return usage("wrong arguments");
    }
  }
  std::ofstream out(argv[1]);
  if (!out) {
    return usage("cannot write the epochs file");
  }
  const std::string config_dir = RF_CONFIG_DIR;
  // The shipped tuning, as the node reads it (only the locator's own keys matter here).
  est::LocatorConfig particle;
  particle.load(rf::YamlParams::fromFile(config_dir + "/locator.yaml"));
  particle.validate();
  est::LocatorConfig solver = particle;
  solver.estimator = est::Estimator::kSolver;

  out << "# kind,case,epoch,x,y,z,value[,rotation row-major]\n";
  std::printf("case,estimator,samples,median_us,p99_us,mean_us\n");
  std::mt19937_64 rng(7);
  for (const std::string name : {"spot", "spot_twr", "tracked", "cube"}) {
    const rf::Layout layout = rf::loadLayoutFile(config_dir + "/layouts/" + name + ".yaml");
    const std::vector<Epoch> epochs = walk(layout, rng);
    writeEpochs(out, name, epochs);

    Timer particle_update, solver_update, solve, thesis;
    timeLocator(layout, particle, epochs, passes, particle_update);
    timeLocator(layout, solver, epochs, passes, solver_update);
    est::SolverConfig solver_config;
    solver_config.height = kHeight;
    const est::PositionSolver position_solver(solver_config);
    timeSolves(epochs, passes, solve,
               [&](const Epoch& e) { return position_solver.solve(e.obs, e.start).success; });
    const thesis_baseline::ThesisSolver thesis_solver(kHeight);
    timeSolves(epochs, passes, thesis,
               [&](const Epoch& e) { return thesis_solver.solve(e.obs, e.start).success; });
    particle_update.print(name, "locator_update_particle");
    solver_update.print(name, "locator_update_solver");
    solve.print(name, "locator_solve");
    thesis.print(name, "thesis_ceres");
  }
  return out ? 0 : 1;
}
