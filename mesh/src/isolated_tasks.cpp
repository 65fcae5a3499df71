// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "isolated_tasks.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <thread>

#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::mesh::detail {
namespace {

/// State shared by the caller and its workers (an anonymous shared mapping).
struct Shared {
  std::atomic<std::size_t> next{0};  // the next position in `tasks` to take
  std::atomic<bool> stop{false};     // the run's time limit is spent: take no more
};
/// Per worker slot: the position it is running (or none) and since when.
struct Slot {
  std::atomic<long long> position{-1};
  std::atomic<double> started{0.0};
};
static_assert(std::atomic<std::size_t>::is_always_lock_free && std::atomic<long long>::is_always_lock_free &&
              std::atomic<double>::is_always_lock_free);

/// Seconds to 3 significant digits (0.0125, 7.5, 60), whole from 100 up (3600).
std::string secondsText(double x) { return x >= 100 ? std::to_string(std::llround(x)) : formatNumber(x, 3); }

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

template <typename T>
T* sharedArray(std::size_t n) {
  void* p = mmap(nullptr, sizeof(T) * n, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw Error(std::string("isolated tasks: mmap failed: ") + std::strerror(errno));
  T* a = static_cast<T*>(p);
  for (std::size_t i = 0; i < n; ++i) new (a + i) T();
  return a;
}

bool writeAll(std::FILE* f, const void* data, std::size_t n) { return std::fwrite(data, 1, n, f) == n; }

/// Record: position (u64), ok (u8), seconds (f64), length (u64), bytes.
void workerLoop(Shared* shared, Slot* slot, std::FILE* out, const std::vector<std::size_t>& tasks,
                const std::function<std::string(std::size_t)>& task) {
  for (;;) {
    const std::size_t pos = shared->next.fetch_add(1);
    if (pos >= tasks.size() || shared->stop.load()) break;
    const double t0 = now();
    slot->started.store(t0);
    slot->position.store(static_cast<long long>(pos));
    std::string bytes;
    std::uint8_t ok = 1;
    try {
      bytes = task(tasks[pos]);
    } catch (const std::exception& e) {
      ok = 0;
      bytes = e.what();
    }
    const std::uint64_t p64 = pos, len = bytes.size();
    const double seconds = now() - t0;
    if (!writeAll(out, &p64, sizeof p64) || !writeAll(out, &ok, 1) || !writeAll(out, &seconds, sizeof seconds) ||
        !writeAll(out, &len, sizeof len) ||
        !writeAll(out, bytes.data(), bytes.size()) || std::fflush(out) != 0)
      _exit(3);
    slot->position.store(-1);
  }
  std::fflush(out);
}

/// Reads the records of one worker's file into `results` (a torn last record is ignored).
void readRecords(std::FILE* f, std::vector<IsolatedResult>& results) {
  std::rewind(f);
  for (;;) {
    std::uint64_t pos = 0, len = 0;
    std::uint8_t ok = 0;
    double seconds = 0;
    if (std::fread(&pos, sizeof pos, 1, f) != 1 || std::fread(&ok, 1, 1, f) != 1 ||
        std::fread(&seconds, sizeof seconds, 1, f) != 1 || std::fread(&len, sizeof len, 1, f) != 1)
      return;
    std::string bytes(len, '\0');
    if (len > 0 && std::fread(bytes.data(), 1, len, f) != len) return;
    if (pos >= results.size()) return;
    IsolatedResult& r = results[pos];
    r.ok = ok != 0;
    r.seconds = seconds;
    r.started = true;
    (r.ok ? r.bytes : r.failure) = std::move(bytes);
  }
}

}  // namespace

std::vector<IsolatedResult> runIsolated(const std::vector<std::size_t>& tasks, int workers, double timeout_seconds,
                                        const std::function<std::string(std::size_t)>& task) {
  return runIsolated(tasks, workers, std::vector<double>(tasks.size(), timeout_seconds),
                     std::numeric_limits<double>::infinity(), task);
}

std::vector<IsolatedResult> runIsolated(const std::vector<std::size_t>& tasks, int workers,
                                        const std::vector<double>& timeouts, double run_seconds,
                                        const std::function<std::string(std::size_t)>& task) {
  const double deadline = now() + run_seconds;
  std::vector<IsolatedResult> results(tasks.size());
  if (tasks.empty()) return results;
  workers = std::max(1, std::min<int>(workers, static_cast<int>(tasks.size())));
  Shared* shared = sharedArray<Shared>(1);
  Slot* slots = sharedArray<Slot>(static_cast<std::size_t>(workers));
  std::vector<pid_t> pids(static_cast<std::size_t>(workers), -1);
  std::vector<std::FILE*> files;
  std::vector<std::string> failures(tasks.size());
  std::vector<double> ran_seconds(tasks.size(), 0.0);  // of the tasks killed
  std::fflush(nullptr);  // a child must not inherit (and flush again) buffered output

  const auto start = [&](std::size_t k) {
    std::FILE* out = std::tmpfile();
    if (!out) throw Error(std::string("isolated tasks: no temporary file: ") + std::strerror(errno));
    files.push_back(out);
    slots[k].position.store(-1);
    const pid_t pid = fork();
    if (pid < 0) throw Error(std::string("isolated tasks: fork failed: ") + std::strerror(errno));
    if (pid == 0) {
      // The host's crash handlers (a test framework's, Python's faulthandler)
      // must not run for a worker: it just dies and is reported.
      for (int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, SIG_DFL);
      workerLoop(shared, &slots[k], out, tasks, task);
      _exit(0);
    }
    pids[k] = pid;
  };
  for (std::size_t k = 0; k < pids.size(); ++k) start(k);

  std::size_t running = pids.size();
  while (running > 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    for (std::size_t k = 0; k < pids.size(); ++k) {
      if (pids[k] < 0) continue;
      int status = 0;
      const pid_t done = waitpid(pids[k], &status, WNOHANG);
      const long long pos = slots[k].position.load();
      std::string why;
      if (done == 0) {
        if (now() > deadline) shared->stop.store(true);
        if (pos < 0) continue;
        const double ran = now() - slots[k].started.load(), limit = timeouts[static_cast<std::size_t>(pos)];
        if (ran <= limit && !(now() > deadline)) continue;
        kill(pids[k], SIGKILL);
        waitpid(pids[k], &status, 0);
        ran_seconds[static_cast<std::size_t>(pos)] = ran;
        why = ran > limit ? "did not finish within " + secondsText(limit) + " s"
                          : "stopped after " + secondsText(ran) + " s at the time limit of the run (" +
                                secondsText(run_seconds) + " s)";
      } else if (WIFSIGNALED(status)) {
        why = std::string("crashed (signal ") + std::to_string(WTERMSIG(status)) + ", " + strsignal(WTERMSIG(status)) + ")";
      } else if (WIFEXITED(status) && WEXITSTATUS(status) != 0) {
        why = "worker exited with status " + std::to_string(WEXITSTATUS(status));
      }
      pids[k] = -1;
      --running;
      if (pos >= 0 && !why.empty()) failures[static_cast<std::size_t>(pos)] = why;
      // A worker that died while tasks are left is replaced.
      if (!why.empty() && shared->next.load() < tasks.size() && !shared->stop.load()) {
        start(k);
        ++running;
      }
    }
  }
  for (std::FILE* f : files) {
    readRecords(f, results);
    std::fclose(f);
  }
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    if (results[i].ok || !results[i].failure.empty()) continue;
    if (!failures[i].empty()) {
      results[i].failure = failures[i];
      results[i].seconds = ran_seconds[i];
      results[i].started = true;
    } else if (shared->stop.load()) {
      results[i].failure = "not started: the time limit of the run (" + secondsText(run_seconds) + " s) was spent";
    } else {
      results[i].failure = "no result (the worker stopped)";
      results[i].started = true;
    }
  }
  munmap(shared, sizeof(Shared));
  munmap(slots, sizeof(Slot) * static_cast<std::size_t>(workers));
  return results;
}

}  // namespace tessella::mesh::detail
