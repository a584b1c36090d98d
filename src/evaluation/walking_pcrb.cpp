// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/walking_pcrb.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "radio_follow/common/angles.hpp"
#include "radio_follow/common/param_error.hpp"
#include "radio_follow/estimation/fisher.hpp"
#include "radio_follow/estimation/posterior_crb.hpp"
#include "radio_follow/models/sensor_tables.hpp"
#include "radio_follow/sim/target_path.hpp"
#include "radio_follow/sim/virtual_sensors.hpp"

namespace radio_follow {
namespace evaluation {
namespace {

/// A run's error beyond this is a mirror or a lost track, not tracking noise, m.
constexpr double kGrossError = 1.0;

/// One sensor report time: which sensor, when.
struct Event {
  double t = 0.0;
  std::size_t sensor = 0;  // modules first, then boards
};

/// Step of the motion-model walk's polyline, s.
constexpr double kModelStep = 0.01;
/// Duration of the motion-model walk, s.
constexpr double kModelDuration = 10.0;

sim::TargetPath walk(WalkShape shape, double speed, double acceleration_psd, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double turn = (2.0 * unit(rng) - 1.0) * kPi;  // the whole path's direction
  const double c = std::cos(turn);
  const double s = std::sin(turn);
  if (shape == WalkShape::kArc) {
    const double radius = 2.5 + 2.5 * unit(rng);
    sim::TargetPath path(Pose2{radius * c, radius * s, turn + kPi / 2.0});
    path.arc(radius, 4.0 * kPi / 3.0, speed);
    return path;
  }
  const double offset = 1.5 + 2.5 * unit(rng);
  sim::TargetPath path(Pose2{-6.0 * c - offset * s, -6.0 * s + offset * c, turn});
  if (shape == WalkShape::kStraight) {
    path.walkTo(6.0 * c - offset * s, 6.0 * s + offset * c, speed);
    return path;
  }
  // The motion model's own process: white acceleration, exactly discretised per step
  // (position and velocity noise correlated as in constantVelocityModel's Q).
  std::normal_distribution<double> normal(0.0, 1.0);
  const double dt = kModelStep;
  const double sv = std::sqrt(acceleration_psd * dt);
  const double sp = std::sqrt(acceleration_psd * dt * dt * dt / 12.0);
  Eigen::Vector2d p(-6.0 * c - offset * s, -6.0 * s + offset * c);
  Eigen::Vector2d v(speed * c, speed * s);
  for (double t = 0.0; t < kModelDuration; t += dt) {
    const Eigen::Vector2d n1(normal(rng), normal(rng));
    const Eigen::Vector2d n2(normal(rng), normal(rng));
    const Eigen::Vector2d next = p + v * dt + sv * dt * 0.5 * n1 + sp * n2;
    v += sv * n1;
    // A chord walked in exactly dt (the polyline's speed is the chord's).
    path.walkTo(next.x(), next.y(), std::max((next - p).norm(), 1e-6) / dt);
    p = next;
  }
  return path;
}

/// The Fisher information (planar block) of one range or bearing of the person at `p`,
/// with the sigma the ideal profile draws its noise with.
Eigen::Matrix2d rangeInformation(const TwrModule& module, const sim::TwrNoise& noise,
                                 const Eigen::Vector3d& p) {
  estimation::ObservationSet obs;
  estimation::RangeObservation z;
  z.module = module.position;
  z.sigma = noise.sigma_scale * models::uwbRangeError((p - module.position).norm()).sigma;
  obs.ranges.push_back(z);
  return estimation::fisherInformation(obs, p).topLeftCorner<2, 2>();
}

Eigen::Matrix2d bearingInformation(const AoaBoard& board, const sim::AoaNoise& noise,
                                   const Eigen::Vector3d& p) {
  // As sim::simulateAoa draws it: the tables' sigma at the direction the array sees (the
  // mirror image through its plane when the person is behind it), on both angles. The
  // mirrored direction's derivatives have the same outer product as the true one's.
  const Eigen::Vector3d local = board.orientation.conjugate() * (p - board.position);
  const double seen_azimuth = std::atan2(local.y(), std::abs(local.x()));
  const double sigma =
      noise.sigma_scale * models::aoaError(board.kind, -seen_azimuth, local.norm()).azimuth_sigma;
  estimation::ObservationSet obs;
  estimation::BearingObservation z;
  z.board = board.position;
  z.rotation = board.orientation.toRotationMatrix();
  z.sigma_azimuth = z.sigma_elevation = sigma;
  obs.bearings.push_back(z);
  return estimation::fisherInformation(obs, p).topLeftCorner<2, 2>();
}

bool inFieldOfView(const AoaBoard& board, const Eigen::Vector3d& p) {
  const Eigen::Vector3d v = (p - board.position).normalized();
  const double off_axis =
      std::acos(std::clamp(board.orientation.toRotationMatrix().col(0).dot(v), -1.0, 1.0));
  return off_axis <= board.field_of_view;
}

/// The bound along one run, advanced measurement by measurement.
class Bound {
 public:
  Bound(const WalkingPcrbParams& p, double acceleration_psd)
      : pcrb_(prior(p)), psd_(acceleration_psd) {}

  void add(double t, const Eigen::Matrix2d& information) {
    if (t > t_) {
      Eigen::Matrix4d f, q;
      estimation::constantVelocityModel(t - t_, psd_, &f, &q);
      pcrb_.predict(f, q);
      t_ = t;
    }
    pcrb_.addInformation(information);
  }
  double positionTrace() const { return pcrb_.bound().topLeftCorner<2, 2>().trace(); }

 private:
  static Eigen::Matrix4d prior(const WalkingPcrbParams& p) {
    const double ip = 1.0 / (p.prior_position_sigma * p.prior_position_sigma);
    const double iv = 1.0 / (p.prior_velocity_sigma * p.prior_velocity_sigma);
    return Eigen::Vector4d(ip, ip, iv, iv).asDiagonal();
  }

  estimation::PosteriorCrb pcrb_;
  double psd_;
  double t_ = 0.0;
};

}  // namespace

WalkShape parseWalkShape(const std::string& text, const std::string& name) {
  require(text == "straight" || text == "arc" || text == "model", name, text,
          "'straight', 'arc' or 'model'");
  return text == "straight" ? WalkShape::kStraight
         : text == "arc"    ? WalkShape::kArc
                            : WalkShape::kModel;
}

std::string toString(WalkShape shape) {
  switch (shape) {
    case WalkShape::kStraight:
      return "straight";
    case WalkShape::kArc:
      return "arc";
    case WalkShape::kModel:
      return "model";
  }
  return "?";
}

WalkingPcrbResult runWalkingPcrb(const Layout& layout, sim::WorldConfig world,
                                 const estimation::LocatorConfig& locator, double locator_rate,
                                 const WalkingPcrbParams& params) {
  require(locator_rate > 0.0, "rate", locator_rate, "a positive update rate (Hz)");
  require(params.min_speed > 0.0 && params.max_speed >= params.min_speed, "speed", params.max_speed,
          "0 < min_speed <= max_speed");
  // The Gaussian case: white noise only, no table bias, no dropouts or occlusions.
  world.twr.use_table_bias = false;
  world.twr.dropout_probability = 0.0;
  world.twr.occlusions.clear();
  world.aoa.use_table_bias = false;
  world.aoa.dropout_probability = 0.0;
  Layout unbiased = layout;
  for (auto& m : unbiased.twr_modules) {
    m.calibration = {0.0, 1.0};
  }
  const std::size_t modules = layout.twr_modules.size();
  const std::size_t sensors = modules + layout.aoa_boards.size();
  std::vector<double> period(sensors, 1.0 / world.rates.twr_hz);
  std::fill(period.begin() + static_cast<std::ptrdiff_t>(modules), period.end(),
            1.0 / world.rates.aoa_hz);
  const double update_period = 1.0 / locator_rate;

  WalkingPcrbResult result;
  double squared_error = 0.0;
  double trace = 0.0;
  double trace_in_fov = 0.0;
  std::vector<double> errors;
  sim::Rng rng(params.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t run = 0; run < params.runs; ++run) {
    const double speed = params.min_speed + (params.max_speed - params.min_speed) * unit(rng);
    const sim::TargetPath path = walk(params.shape, speed, locator.process_noise, rng);
    const auto truth = [&](double t) {
      const sim::TargetSample s = path.at(t);
      return Eigen::Vector3d(s.pose.x, s.pose.y, locator.height);
    };
    estimation::Locator estimator(unbiased, locator);
    Bound all(params, locator.process_noise);
    Bound in_fov(params, locator.process_noise);
    std::vector<double> next(sensors);
    for (std::size_t s = 0; s < sensors; ++s) {
      next[s] = period[s] * unit(rng);  // free-running sensors: each its own phase
    }
    bool gross = false;
    std::vector<Event> events;
    for (double now = update_period; now <= path.duration() + 1e-9; now += update_period) {
      events.clear();
      for (std::size_t s = 0; s < sensors; ++s) {
        for (; next[s] <= now; next[s] += period[s]) {
          events.push_back({next[s], s});
        }
      }
      std::sort(events.begin(), events.end(),
                [](const Event& a, const Event& b) { return a.t < b.t; });
      for (const Event& e : events) {
        const Eigen::Vector3d p = truth(e.t);
        if (e.sensor < modules) {
          const TwrModule& m = layout.twr_modules[e.sensor];
          const std::optional<double> range = sim::simulateTwrRange(m, world.twr, p, rng);
          if (range) {
            estimator.addRange(e.sensor, *range, e.t);
            const Eigen::Matrix2d info = rangeInformation(m, world.twr, p);
            all.add(e.t, info);
            in_fov.add(e.t, info);
          }
          continue;
        }
        const AoaBoard& b = layout.aoa_boards[e.sensor - modules];
        const std::optional<sim::AoaSample> sample = sim::simulateAoa(b, world.aoa, p, rng);
        if (sample) {
          estimator.addBearing(e.sensor - modules, sample->azimuth, sample->elevation, sample->rssi,
                               e.t);
          const Eigen::Matrix2d info = bearingInformation(b, world.aoa, p);
          all.add(e.t, info);
          in_fov.add(e.t, inFieldOfView(b, p) ? info : Eigen::Matrix2d::Zero());
        }
      }
      const estimation::LocatorEstimate estimate = estimator.update(now);
      if (now < params.warm_up) {
        continue;
      }
      if (!hasPosition(estimate.status)) {
        ++result.without_position;
        continue;
      }
      // The estimate is of the person at its stamp (the newest measurement it used); the
      // bound is after the newest measurement, at most one sensor period later.
      const sim::TargetSample s = path.at(estimate.stamp);
      const Eigen::Vector2d error =
          estimate.position.head<2>() - Eigen::Vector2d(s.pose.x, s.pose.y);
      const Eigen::Vector2d along(std::cos(s.pose.yaw), std::sin(s.pose.yaw));
      squared_error += error.squaredNorm();
      trace += all.positionTrace();
      trace_in_fov += in_fov.positionTrace();
      result.along_mean += error.dot(along);
      result.across_mean += error.dot(Eigen::Vector2d(-along.y(), along.x()));
      errors.push_back(error.norm());
      gross = gross || error.norm() > kGrossError;
      ++result.samples;
    }
    result.runs_over_1m += gross;
    ++result.runs;
  }
  if (result.samples > 0) {
    const double n = static_cast<double>(result.samples);
    result.rmse = std::sqrt(squared_error / n);
    result.pcrb = std::sqrt(trace / n);
    result.pcrb_in_fov = std::sqrt(trace_in_fov / n);
    result.along_mean /= n;
    result.across_mean /= n;
    std::nth_element(errors.begin(),
                     errors.begin() + static_cast<std::ptrdiff_t>(errors.size() / 2), errors.end());
    result.median_error = errors[errors.size() / 2];
  }
  return result;
}

}  // namespace evaluation
}  // namespace radio_follow
