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

TEST_CASE("isolated tasks: a time limit per task and one for the whole run", "[mesh][isolated]") {
  // Per task: task 1 (sleeping) is cut at its own limit, task 0 (quick) has a long one.
  const auto sleeper = [](std::size_t i) -> std::string {
    if (i != 0) std::this_thread::sleep_for(std::chrono::seconds(30));
    return "done " + std::to_string(i);
  };
  const auto each = runIsolated({0, 1}, 2, std::vector<double>{10.0, 0.2}, 1e9, sleeper);
  REQUIRE(each.size() == 2);
  CHECK(each[0].ok);
  CHECK(each[0].bytes == "done 0");
  CHECK(each[0].started);
  CHECK(each[0].seconds < 10.0);
  CHECK_FALSE(each[1].ok);
  CHECK(each[1].started);
  CHECK_THAT(each[1].failure, Catch::Contains("did not finish within 0.2 s"));
  CHECK(each[1].seconds >= 0.2);
  // The run: one worker, three sleeping tasks with long limits of their own; at the run's limit the first is
  // stopped and the others never start.
  const auto run = runIsolated({1, 2, 3}, 1, std::vector<double>(3, 100.0), 0.3, sleeper);
  REQUIRE(run.size() == 3);
  CHECK_FALSE(run[0].ok);
  CHECK(run[0].started);
  CHECK_THAT(run[0].failure, Catch::Contains("at the time limit of the run (0.3 s)"));
  CHECK(run[0].seconds > 0.1);  // from when it started, a little after the call
  for (std::size_t k : {1u, 2u}) {
    INFO("task " << k);
    CHECK_FALSE(run[k].ok);
    CHECK_FALSE(run[k].started);
    CHECK(run[k].seconds == 0.0);
    CHECK_THAT(run[k].failure, Catch::Contains("not started: the time limit of the run (0.3 s) was spent"));
  }
}
