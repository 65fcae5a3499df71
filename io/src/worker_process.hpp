// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal: runs one task in a forked worker process, so that code which may
// crash on bad input (VTK 9.1's XML reader dereferences, divides and
// allocates whatever a damaged file says) costs the worker, not the caller.
// The worker inherits the caller's memory (copy-on-write); its only output is
// the string the task returns; what it prints is captured and handed back.
// It gets an address-space limit and a time limit, and its crash handlers
// and core dumps are off.

#include <cstddef>
#include <functional>
#include <string>

namespace tessella::io::detail {

struct WorkerOutcome {
  bool ok = false;     ///< the task returned normally
  bool threw = false;  ///< the task threw (other than std::bad_alloc)
  /// What the task returned (ok), its exception's message (threw), or how the
  /// worker failed: "crashed (signal 11: Segmentation fault)", "ran out of
  /// memory (...)", "did not finish within N s".
  std::string output;
  /// What the worker printed (stdout and stderr) while the task ran, at most
  /// 64 KiB; it is not shown to the caller's user.
  std::string printed;
};

/// Runs `task` in a child process that may use `memory_budget` bytes of
/// address space beyond the caller's and `timeout_seconds` of time. Throws
/// tessella::Error when no child can be started (fork or pipe failing).
WorkerOutcome runInWorker(const std::function<std::string()>& task, std::size_t memory_budget,
                          double timeout_seconds);

}  // namespace tessella::io::detail
