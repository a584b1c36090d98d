// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow {
namespace estimation {

/// Robust loss applied to one measurement kind's whitened residuals in the solver.
enum class LossType { kNone, kHuber, kSoftL1, kCauchy };

struct LossConfig {
  LossType type = LossType::kNone;
  /// Residual size (in sigmas) where the loss starts to down-weight.
  double scale = 1.0;
};

/// "none" | "huber" | "soft_l1" | "cauchy"; throws ParamError naming `parameter` otherwise.
inline LossType parseLossType(const std::string& text, const std::string& parameter) {
  if (text == "none")
    return LossType::kNone;
  if (text == "huber")
    return LossType::kHuber;
  if (text == "soft_l1")
    return LossType::kSoftL1;
  if (text == "cauchy")
    return LossType::kCauchy;
  throw ParamError(parameter, paramValueString(text), "one of none, huber, soft_l1, cauchy");
}

inline std::string toString(LossType type) {
  switch (type) {
    case LossType::kHuber:
      return "huber";
    case LossType::kSoftL1:
      return "soft_l1";
    case LossType::kCauchy:
      return "cauchy";
    case LossType::kNone:
      break;
  }
  return "none";
}

}  // namespace estimation
}  // namespace radio_follow
