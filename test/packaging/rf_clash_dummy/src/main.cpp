// SPDX-License-Identifier: BSD-3-Clause
// Prints its own target name: proof that this package's binary ran, not radio_follow's.
#include <cstdio>

int main() {
  std::puts(RF_CLASH_NAME);
  return 0;
}
