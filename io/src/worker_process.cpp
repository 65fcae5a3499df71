// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "worker_process.hpp"

#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <exception>
#include <fstream>
#include <new>

#include "tessella/tissue/errors.hpp"

namespace tessella::io::detail {
namespace {

// The first byte of the worker's report says how the task ended.
constexpr char kReturned = 'r', kThrew = 't', kOutOfMemory = 'm';

/// Bytes of address space the process uses now (0 if unknown).
std::size_t addressSpaceInUse() {
  std::ifstream statm("/proc/self/statm");
  unsigned long long pages = 0;
  if (!(statm >> pages)) return 0;
  return static_cast<std::size_t>(pages) * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

void limitWorker(std::size_t memory_budget) {
  // The host's crash handlers (a test framework's, Python's faulthandler)
  // must not run in the worker: it just dies, and the caller reports it.
  for (int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGPIPE}) std::signal(sig, SIG_DFL);
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  if (const std::size_t in_use = addressSpaceInUse(); in_use > 0) {
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0) {
      const rlim_t wanted = static_cast<rlim_t>(in_use) + static_cast<rlim_t>(memory_budget);
      as.rlim_cur = as.rlim_max == RLIM_INFINITY ? wanted : std::min(wanted, as.rlim_max);
      setrlimit(RLIMIT_AS, &as);
    }
  }
}

void writeAll(int fd, const std::string& bytes) {
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

/// What the worker printed, from the start of `file` (at most kMaxPrinted bytes).
constexpr std::size_t kMaxPrinted = 64 * 1024;

std::string printedTo(std::FILE* file) {
  std::string text;
  if (!file) return text;
  std::fflush(nullptr);
  std::rewind(file);
  char buffer[4096];
  for (std::size_t n; text.size() < kMaxPrinted && (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;)
    text.append(buffer, n);
  if (text.size() > kMaxPrinted) text.resize(kMaxPrinted);
  return text;
}

[[noreturn]] void workerMain(int fd, const std::function<std::string()>& task, std::size_t memory_budget) {
  limitWorker(memory_budget);
  // What the task's libraries print goes to a file that is part of the
  // report, not to the caller's terminal.
  std::FILE* printed = std::tmpfile();
  if (printed) {
    std::fflush(nullptr);
    dup2(fileno(printed), STDOUT_FILENO);
    dup2(fileno(printed), STDERR_FILENO);
  }
  std::string report;
  try {
    report = kReturned + task();
  } catch (const std::bad_alloc&) {
    report = std::string(1, kOutOfMemory);
  } catch (const std::exception& e) {
    report = kThrew + std::string(e.what());
  } catch (...) {
    report = kThrew + std::string("an unknown exception");
  }
  // kind, length of the task's output, the output, what was printed
  const std::uint64_t length = report.size() - 1;
  report.insert(1, reinterpret_cast<const char*>(&length), sizeof length);
  report += printedTo(printed);
  writeAll(fd, report);
  _exit(0);  // no atexit handlers, no flushing of the caller's buffers
}

std::string mebibytes(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

}  // namespace

WorkerOutcome runInWorker(const std::function<std::string()>& task, std::size_t memory_budget,
                          double timeout_seconds) {
  int fds[2];
  if (pipe(fds) != 0) throw Error(std::string("cannot start a worker process: pipe failed: ") + std::strerror(errno));
  std::fflush(nullptr);  // the worker must not inherit (and flush again) buffered output
  const pid_t pid = fork();
  if (pid < 0) {
    const int err = errno;
    close(fds[0]);
    close(fds[1]);
    throw Error(std::string("cannot start a worker process: fork failed: ") + std::strerror(err));
  }
  if (pid == 0) {
    close(fds[0]);
    workerMain(fds[1], task, memory_budget);
  }
  close(fds[1]);

  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_seconds));
  std::string report;
  bool timed_out = false;
  char buffer[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file: the worker is done (or dead)
    report.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  if (timed_out) kill(pid, SIGKILL);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }

  if (timed_out)
    return {false, false, "did not finish within " + std::to_string(static_cast<long long>(timeout_seconds)) + " s", {}};
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* name = strsignal(sig);
    return {false, false, "crashed (signal " + std::to_string(sig) + ": " + (name ? name : "unknown") + ")", {}};
  }
  std::uint64_t length = 0;
  if (report.size() < 1 + sizeof length)
    return {false, false, "ended without a report (exit status " + std::to_string(WEXITSTATUS(status)) + ")", {}};
  std::memcpy(&length, report.data() + 1, sizeof length);
  if (length > report.size() - 1 - sizeof length) return {false, false, "sent a report that makes no sense", {}};
  std::string output = report.substr(1 + sizeof length, length);
  std::string printed = report.substr(1 + sizeof length + length);
  switch (report[0]) {
    case kReturned: return {true, false, std::move(output), std::move(printed)};
    case kThrew: return {false, true, std::move(output), std::move(printed)};
    case kOutOfMemory:
      return {false, false, "ran out of memory (it may use " + mebibytes(memory_budget) + ")", std::move(printed)};
    default: return {false, false, "sent a report that makes no sense", {}};
  }
}

}  // namespace tessella::io::detail
