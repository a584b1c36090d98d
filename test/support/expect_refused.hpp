// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// For parameter-validation tests: a valid parameter struct with one change must be refused
// by validate() with a ParamError naming the changed parameter.

#include <gtest/gtest.h>

#include <string>

#include "radio_follow/common/param_error.hpp"

namespace radio_follow::test {

template <typename Params, typename Change>
void expectRefused(const Params& valid, Change change, const std::string& name) {
  Params p = valid;
  change(p);
  try {
    p.validate();
    ADD_FAILURE() << name << " accepted";
  } catch (const ParamError& e) {
    EXPECT_EQ(e.name(), name);
  }
}

}  // namespace radio_follow::test
