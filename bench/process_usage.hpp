// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What the bench programs read of their own process besides the wall clock:
// CPU time (on a shared machine the wall clock also counts the time other
// processes hold the cores, so a CPU ratio is the steadier figure; OpenMP
// threads spinning at a barrier count too), peak memory and page faults.

#include <sys/resource.h>

#include <ctime>

namespace tessella::bench {

/// CPU seconds of this process so far, all its threads.
inline double processCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// CPU seconds of the calling thread so far.
inline double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// CPU seconds of this process's children that have been waited for (e.g. the mesher's worker processes).
inline double childrenCpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// Peak resident memory of this process so far, in MB (it only grows: a step's own use is the rise).
inline double maxRssMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

/// Minor page faults of this process so far (first touches of fresh memory, mostly).
inline long minorPageFaults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

}  // namespace tessella::bench
