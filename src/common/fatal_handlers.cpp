// SPDX-License-Identifier: BSD-3-Clause
#include "radio_follow/common/fatal_handlers.hpp"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>
#include <string>

namespace radio_follow {
namespace {

// A signal handler can only reach static storage: the last words, the linger and a
// once-flag live here, set by installFatalHandlers before any handler can run.
std::function<void(const char*)>& lastWords() {
  static std::function<void(const char*)> words;
  return words;
}
double linger = 0.0;
std::atomic<bool> dying{false};

constexpr int kFatalSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};

void writeStderr(const char* text) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

// Once: the reason, the last words, the linger. A second fatal event (the abort after
// terminate, a crash inside the last words) goes straight to the default action.
void speakOnce(const char* reason) {
  if (dying.exchange(true)) {
    return;
  }
  std::signal(SIGALRM, SIG_DFL);
  ::alarm(kLastWordsDeadline);
  writeStderr("radio_follow: fatal: ");
  writeStderr(reason);
  writeStderr("\n");
  if (lastWords()) {
    try {
      lastWords()(reason);
    } catch (...) {
      writeStderr("radio_follow: fatal: the last words threw\n");
    }
  }
  if (linger > 0.0) {
    timespec t{};
    t.tv_sec = static_cast<time_t>(linger);
    t.tv_nsec = static_cast<long>((linger - std::floor(linger)) * 1e9);
    ::nanosleep(&t, nullptr);
  }
}

const char* signalName(int signal) {
  switch (signal) {
    case SIGSEGV:
      return "fatal signal SIGSEGV (invalid memory access)";
    case SIGBUS:
      return "fatal signal SIGBUS";
    case SIGFPE:
      return "fatal signal SIGFPE";
    case SIGILL:
      return "fatal signal SIGILL";
    case SIGABRT:
      return "fatal signal SIGABRT (abort)";
    default:
      return "fatal signal";
  }
}

void onFatalSignal(int signal) {
  speakOnce(signalName(signal));
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void onTerminate() {
  std::string reason = "std::terminate without an exception";
  if (const std::exception_ptr e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::exception& x) {
      reason = std::string("uncaught exception: ") + x.what();
    } catch (...) {
      reason = "uncaught exception of unknown type";
    }
  }
  speakOnce(reason.c_str());
  std::signal(SIGABRT, SIG_DFL);
  std::abort();
}

}  // namespace

void installFatalHandlers(std::function<void(const char* reason)> last_words,
                          double linger_seconds) {
  lastWords() = std::move(last_words);
  linger = std::isfinite(linger_seconds) && linger_seconds > 0.0 ? linger_seconds : 0.0;
  std::set_terminate(onTerminate);
  for (const int signal : kFatalSignals) {
    std::signal(signal, onFatalSignal);
  }
}

}  // namespace radio_follow
