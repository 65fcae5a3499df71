// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Tasks in worker processes (mesh/src/isolated_tasks.hpp, internal): a task
// that aborts, hangs or throws costs that task, never the caller, and the
// other tasks' results come back in order.

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "../../mesh/src/isolated_tasks.hpp"

using tessella::mesh::detail::runIsolated;

TEST_CASE("isolated tasks: results in order, failures reported, the caller survives", "[mesh][isolated]") {
  const std::vector<std::size_t> tasks = {0, 1, 2, 3, 4, 5, 6, 7};
  const int workers = GENERATE(1, 2, 3);
  const auto results = runIsolated(tasks, workers, 1.0, [](std::size_t i) -> std::string {
    if (i == 2) std::abort();                                                    // like a failed TetGen assertion
    if (i == 4) std::this_thread::sleep_for(std::chrono::seconds(30));           // never ends (for the limit)
    if (i == 6) throw std::runtime_error("task six refused");
    return std::string(i + 1, static_cast<char>('a' + i));
  });
  REQUIRE(results.size() == tasks.size());
  for (std::size_t i : {0u, 1u, 3u, 5u, 7u}) {
    INFO("task " << i);
    CHECK(results[i].ok);
    CHECK(results[i].bytes == std::string(i + 1, static_cast<char>('a' + i)));
  }
  CHECK_FALSE(results[2].ok);
  CHECK_THAT(results[2].failure, Catch::Contains("signal 6"));
  CHECK_FALSE(results[4].ok);
  CHECK_THAT(results[4].failure, Catch::Contains("did not finish within 1 s"));
  CHECK_FALSE(results[6].ok);
  CHECK(results[6].failure == "task six refused");
}

TEST_CASE("isolated tasks: a subset of task ids, and none", "[mesh][isolated]") {
  const auto results = runIsolated({9, 3}, 2, 10.0, [](std::size_t i) { return std::to_string(i * i); });
  REQUIRE(results.size() == 2);
  CHECK(results[0].bytes == "81");
  CHECK(results[1].bytes == "9");
  CHECK(runIsolated({}, 2, 1.0, [](std::size_t) { return std::string(); }).empty());
}
