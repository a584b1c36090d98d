// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>

namespace radio_follow {

/// Most seconds the last words may take before the process dies anyway (SIGALRM): they
/// may block on a lock the failing thread held.
constexpr unsigned kLastWordsDeadline = 2;

/// What a node does when it must die (issue 34): an uncaught exception (std::terminate)
/// or a fatal signal (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT). Once per process:
/// writes why to stderr, runs `last_words(reason)` (a controller publishes zero cmd_vel
/// and logs), sleeps `linger_seconds` so that what they sent leaves the process, then dies
/// by the default action of the signal (exit code 128 + signal: roslaunch's respawn sees
/// a crash). Calling it again replaces the last words.
///
/// The last words run inside a signal handler, where only async-signal-safe calls are
/// defined; publishing a message is not one. They are a best effort, bounded by
/// kLastWordsDeadline: a robot told to stop by a process that might hang is better off
/// than one left on its last command.
void installFatalHandlers(std::function<void(const char* reason)> last_words,
                          double linger_seconds);

}  // namespace radio_follow
