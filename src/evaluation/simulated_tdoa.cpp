// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/evaluation/simulated_tdoa.hpp"

namespace radio_follow {
namespace evaluation {

void feedTdoaBlink(estimation::Locator& locator, const Layout& layout, std::size_t reference,
                   const std::vector<double>& differences, std::optional<std::size_t> module,
                   double variance, double t, const std::optional<Pose2>& pose) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < layout.tdoa_anchors.size() && k < differences.size(); ++i) {
    if (i == reference) {
      continue;
    }
    if (module) {
      locator.addTdoaCalibration(*module, i, reference, differences[k++], t);
    } else {
      locator.addTdoa(i, reference, differences[k++], variance, t, pose);
    }
  }
}

}  // namespace evaluation
}  // namespace radio_follow
