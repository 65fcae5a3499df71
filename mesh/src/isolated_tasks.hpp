// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: runs tasks in forked worker processes, so that a task that aborts
// (TetGen 1.5 is built with assertions on and calls abort()), crashes or
// never ends costs that task, not the caller's process. Workers inherit the
// caller's memory (copy-on-write), take tasks from a shared counter, and
// write each result to their own unlinked temporary file; the caller reads
// the files once all workers are gone. A worker that dies or overruns the
// time limit is replaced and its task reported as failed.
//
// Separate processes also make non-reentrant code (TetGen's predicates keep
// globals) safe to run side by side.

#include <functional>
#include <string>
#include <vector>

namespace tessella::mesh::detail {

struct IsolatedResult {
  bool ok = false;
  std::string bytes;    ///< what the task returned, when ok
  std::string failure;  ///< why not: the task's exception, the signal, the time limit
  double seconds = 0;   ///< how long the task ran (wall clock; 0 if it never started)
  bool started = false; ///< false: not run, the run's time limit (`run_seconds`) spent first
};

/// Runs task(i) for i in `tasks` on up to `workers` processes; a task taking
/// longer than `timeout_seconds` is killed. Results in the order of `tasks`.
/// The task runs in a child process: it must not touch threads or state the
/// caller needs to see (its only output is the string it returns).
std::vector<IsolatedResult> runIsolated(const std::vector<std::size_t>& tasks, int workers, double timeout_seconds,
                                        const std::function<std::string(std::size_t)>& task);

/// As above, with a time limit per task (`timeouts[k]` for `tasks[k]`) and one
/// for the whole call: once `run_seconds` have passed since the call, running
/// tasks are killed ("stopped at the time limit of ...") and no other starts
/// (IsolatedResult::started false).
std::vector<IsolatedResult> runIsolated(const std::vector<std::size_t>& tasks, int workers,
                                        const std::vector<double>& timeouts, double run_seconds,
                                        const std::function<std::string(std::size_t)>& task);

}  // namespace tessella::mesh::detail
