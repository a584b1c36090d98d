// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/error_statistics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "radio_follow/common/angles.hpp"

namespace radio_follow {

double quantile(std::vector<double> values, double q) {
  if (values.empty()) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const std::size_t k = static_cast<std::size_t>(q * (values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

std::optional<double> nees2d(const Eigen::Vector2d& error, const Eigen::Matrix2d& covariance) {
  if (!covariance.allFinite() || !(covariance.determinant() > 0.0)) {
    return std::nullopt;
  }
  return error.dot(covariance.ldlt().solve(error));
}

double shareInside95(const std::vector<double>& nees_2d) {
  constexpr double kChiSquare2Dof95 = 5.991;
  if (nees_2d.empty()) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const auto inside =
      std::count_if(nees_2d.begin(), nees_2d.end(), [](double v) { return v <= kChiSquare2Dof95; });
  return static_cast<double>(inside) / static_cast<double>(nees_2d.size());
}

double mean(const std::vector<double>& values) {
  if (values.empty()) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  double sum = 0.0;
  for (double v : values) {
    sum += v;
  }
  return sum / values.size();
}

ErrorSummary summarize(const std::vector<double>& errors) {
  ErrorSummary s;
  s.count = errors.size();
  s.mean = mean(errors);
  s.median = quantile(errors, 0.5);
  s.p95 = quantile(errors, 0.95);
  s.max = errors.empty() ? std::numeric_limits<double>::quiet_NaN()
                         : *std::max_element(errors.begin(), errors.end());
  return s;
}

std::size_t ErrorStatistics::sectorOf(double bearing) {
  const double width = 2.0 * kPi / kSectors;
  double a = std::fmod(bearing + 0.5 * width, 2.0 * kPi);
  if (a < 0.0) {
    a += 2.0 * kPi;
  }
  return std::min(kSectors - 1, static_cast<std::size_t>(a / width));
}

std::string ErrorStatistics::bandName(std::size_t i) {
  std::ostringstream out;
  out << (i == 0 ? 0.0 : kBandEdges.at(i - 1));
  if (i < kBandEdges.size()) {
    out << "-" << kBandEdges[i] << " m";
  } else {
    out << "+ m";
  }
  return out.str();
}

void ErrorStatistics::add(double truth_x, double truth_y, double error) {
  if (!std::isfinite(truth_x) || !std::isfinite(truth_y) || !std::isfinite(error)) {
    return;
  }
  all_.push_back(error);
  sectors_[sectorOf(std::atan2(truth_y, truth_x))].push_back(error);
  const double distance = std::hypot(truth_x, truth_y);
  std::size_t band = 0;
  while (band < kBandEdges.size() && distance >= kBandEdges[band]) {
    ++band;
  }
  bands_[band].push_back(error);
}

std::string jsonNumber(double v) {
  if (!std::isfinite(v)) {
    return "null";
  }
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\u%04x", static_cast<unsigned>(c));
      out += buffer;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

namespace {

std::string json(const ErrorSummary& s) {
  std::ostringstream out;
  out << "{\"count\": " << s.count << ", \"mean_m\": " << jsonNumber(s.mean)
      << ", \"median_m\": " << jsonNumber(s.median) << ", \"p95_m\": " << jsonNumber(s.p95)
      << ", \"max_m\": " << jsonNumber(s.max) << "}";
  return out.str();
}

}  // namespace

std::string ErrorStatistics::toJson() const {
  std::ostringstream out;
  out << "{\n  \"overall\": " << json(overall()) << ",\n  \"by_sector\": [";
  for (std::size_t i = 0; i < kSectors; ++i) {
    out << (i ? ", " : "") << "\n    {\"center_deg\": " << i * 360 / kSectors
        << ", \"errors\": " << json(sector(i)) << "}";
  }
  out << "\n  ],\n  \"by_distance\": [";
  for (std::size_t i = 0; i < bands_.size(); ++i) {
    out << (i ? ", " : "") << "\n    {\"band\": \"" << bandName(i)
        << "\", \"errors\": " << json(band(i)) << "}";
  }
  out << "\n  ]\n}\n";
  return out.str();
}

double missAtTarget(const Eigen::Vector2d& target, double heading) {
  const Eigen::Vector2d along(std::cos(heading), std::sin(heading));
  const double ahead = target.dot(along);
  return ahead > 0.0 ? std::abs(along.x() * target.y() - along.y() * target.x()) : target.norm();
}

void HeadingStatistics::add(const std::string& status, double heading_error_deg, double miss) {
  if (!std::isfinite(heading_error_deg) || !std::isfinite(miss)) {
    return;
  }
  for (Samples* s : {&all_, &by_status_[status]}) {
    s->heading.push_back(heading_error_deg);
    s->miss.push_back(miss);
  }
}

ErrorSummary HeadingStatistics::headingError(const std::string& status) const {
  if (status.empty()) {
    return summarize(all_.heading);
  }
  const auto it = by_status_.find(status);
  return summarize(it == by_status_.end() ? std::vector<double>() : it->second.heading);
}

ErrorSummary HeadingStatistics::miss(const std::string& status) const {
  if (status.empty()) {
    return summarize(all_.miss);
  }
  const auto it = by_status_.find(status);
  return summarize(it == by_status_.end() ? std::vector<double>() : it->second.miss);
}

std::vector<std::string> HeadingStatistics::statuses() const {
  std::vector<std::string> out;
  for (const auto& kv : by_status_) {
    out.push_back(kv.first);
  }
  return out;
}

std::string HeadingStatistics::toJson() const {
  const auto summary = [](const ErrorSummary& s) {
    std::ostringstream out;
    out << "{\"mean\": " << jsonNumber(s.mean) << ", \"median\": " << jsonNumber(s.median)
        << ", \"p95\": " << jsonNumber(s.p95) << ", \"max\": " << jsonNumber(s.max) << "}";
    return out.str();
  };
  const auto entry = [&](const std::string& name, const std::string& status) {
    return jsonString(name) + ": {\"count\": " + std::to_string(headingError(status).count) +
           ", \"heading_error_deg\": " + summary(headingError(status)) +
           ", \"miss_m\": " + summary(miss(status)) + "}";
  };
  std::string out = "{" + entry("all", "");
  for (const std::string& status : statuses()) {
    out += ", " + entry(status, status);
  }
  return out + "}";
}

}  // namespace radio_follow
