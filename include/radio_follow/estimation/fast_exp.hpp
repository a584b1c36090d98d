// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <cstring>

namespace radio_follow {
namespace estimation {

/// exp(x) in single precision for the particle filter's likelihoods, with fewer
/// operations than Eigen's vectorised exp (which keeps the last bit and the whole float
/// range): x clamped to [-86, 88] (results stay normal
/// floats), 2^(x log2 e) split into a rounded integer n (adding and subtracting
/// 1.5 * 2^23) and a fraction f in [-1/2, 1/2], 2^f from its degree-5 Taylor polynomial,
/// n added to the result's exponent bits. Relative error below 4e-6 for |x| <= 10 and
/// 1e-5 over the whole range (x log2 e rounded to a float), far below what a likelihood
/// needs. The scalar and the vector versions do the same single-precision
/// operations in the same order (no fused multiply-add on baseline x86-64), so the
/// elements Eigen takes one at a time at an array's end get the values a vector would.
struct FastExp {
  static constexpr float kLow = -86.0f;
  static constexpr float kHigh = 88.0f;
  static constexpr float kLog2e = 1.44269504f;
  static constexpr float kRound = 12582912.0f;  ///< 1.5 * 2^23
  static constexpr std::int32_t kRoundBits = 0x4B400000;
  static constexpr int kDegree = 5;
  /// ln(2)^k / k!, k = 5 .. 0 (Horner's order).
  static constexpr float kCoefficients[kDegree + 1] = {1.3333558e-3f, 9.6181291e-3f, 5.5504109e-2f,
                                                       2.4022651e-1f, 6.9314718e-1f, 1.0f};

  float operator()(float x) const {
    x = std::min(std::max(x, kLow), kHigh);
    const float t = x * kLog2e;
    const float y = t + kRound;
    const float f = t - (y - kRound);
    float p = kCoefficients[0];
    for (int k = 1; k <= kDegree; ++k) {
      p = p * f + kCoefficients[k];
    }
    std::uint32_t p_bits;
    std::uint32_t y_bits;
    std::memcpy(&p_bits, &p, sizeof p);
    std::memcpy(&y_bits, &y, sizeof y);
    p_bits += (y_bits - static_cast<std::uint32_t>(kRoundBits)) << 23;
    std::memcpy(&p, &p_bits, sizeof p);
    return p;
  }

  template <typename Packet>
  Packet packetOp(const Packet& x_in) const {
    namespace ei = Eigen::internal;
    using PacketI = typename ei::unpacket_traits<Packet>::integer_packet;
    const Packet x = ei::pmin(ei::pmax(x_in, ei::pset1<Packet>(kLow)), ei::pset1<Packet>(kHigh));
    const Packet t = ei::pmul(x, ei::pset1<Packet>(kLog2e));
    const Packet y = ei::padd(t, ei::pset1<Packet>(kRound));
    const Packet f = ei::psub(t, ei::psub(y, ei::pset1<Packet>(kRound)));
    Packet p = ei::pset1<Packet>(kCoefficients[0]);
    for (int k = 1; k <= kDegree; ++k) {
      p = ei::padd(ei::pmul(p, f), ei::pset1<Packet>(kCoefficients[k]));
    }
    const PacketI n = ei::psub(ei::preinterpret<PacketI>(y), ei::pset1<PacketI>(kRoundBits));
    return ei::preinterpret<Packet>(
        ei::padd(ei::preinterpret<PacketI>(p), ei::plogical_shift_left<23>(n)));
  }
};

/// e^x of every element of a float array expression (see FastExp).
template <typename Derived>
auto fastExp(const Eigen::ArrayBase<Derived>& x) {
  return x.unaryExpr(FastExp());
}

/// 1 where x > 0, 0 where x <= 0 (for |x| > 1e-30), with arithmetic only: Eigen
/// vectorises it, where it evaluates an expression containing a select element by element.
template <typename Derived>
auto positiveStep(const Eigen::ArrayBase<Derived>& x) {
  return (x * 1e30f).max(0.0f).min(1.0f);
}

}  // namespace estimation
}  // namespace radio_follow

namespace Eigen {
namespace internal {
template <>
struct functor_traits<radio_follow::estimation::FastExp> {
  enum { Cost = 12 * NumTraits<float>::MulCost, PacketAccess = packet_traits<float>::Vectorizable };
};
}  // namespace internal
}  // namespace Eigen
