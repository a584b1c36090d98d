// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/fatal_handlers.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace radio_follow {
namespace {

void sayLastWords(const char* reason) {
  std::fprintf(stderr, "LAST WORDS (%s)\n", reason);
  std::fflush(stderr);
}

// An exception that escapes a thread (a callback outside any barrier) ends in
// std::terminate: the last words run with the exception's text, then the process aborts.
TEST(FatalHandlersDeathTest, UncaughtExceptionSpeaksThenAborts) {
  EXPECT_EXIT(
      {
        installFatalHandlers(sayLastWords, 0.01);
        std::thread([] {
          throw std::runtime_error("Duration is out of dual 32-bit range");
        }).join();
      },
      ::testing::KilledBySignal(SIGABRT),
      "LAST WORDS \\(uncaught exception: Duration is out of dual 32-bit range\\)");
}

TEST(FatalHandlersDeathTest, FatalSignalSpeaksThenDiesBySignal) {
  EXPECT_EXIT(
      {
        installFatalHandlers(sayLastWords, 0.0);
        std::raise(SIGSEGV);
      },
      ::testing::KilledBySignal(SIGSEGV), "LAST WORDS \\(fatal signal SIGSEGV");
}

// The last words run once: a crash inside them does not run them again.
TEST(FatalHandlersDeathTest, LastWordsRunOnce) {
  EXPECT_EXIT(
      {
        installFatalHandlers(
            [](const char* reason) {
              sayLastWords(reason);
              std::raise(SIGFPE);
            },
            0.0);
        std::raise(SIGSEGV);
      },
      ::testing::KilledBySignal(SIGFPE), "LAST WORDS \\(fatal signal SIGSEGV");
}

// Last words that hang (a lock the failing thread held) cannot keep the process alive.
TEST(FatalHandlersDeathTest, HangingLastWordsStillDie) {
  EXPECT_EXIT(
      {
        installFatalHandlers(
            [](const char* reason) {
              sayLastWords(reason);
              for (;;) {
                pause();
              }
            },
            0.0);
        std::terminate();
      },
      ::testing::KilledBySignal(SIGALRM), "LAST WORDS \\(std::terminate without an exception\\)");
}

}  // namespace
}  // namespace radio_follow
