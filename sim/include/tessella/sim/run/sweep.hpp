// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Parameter sweeps: one config per combination of the varied keys and per
// replicate, and a Snakemake workflow that runs them and collects every run's
// final statistics (the last row of its stats.csv) into sweep.csv.
//
//   tessella sweep configs/voronoi_growth.yaml --vary division.size=1.5,2
//                 --vary growth.uniform.rate=0.05,0.1 --replicates 3 --out sweeps/s1
//   cd sweeps/s1 && snakemake -j 2          # or on a cluster: --profile / --slurm
//
// Every combination is validated against the schema before anything is
// written (an error names the --vary or --set and the value). Replicate r
// runs with rng_seed = base + r, the same seeds for every combination (common
// random numbers, so parameter effects are not confounded with seed effects);
// base is the config's rng_seed, else 1.

#include <cstdint>
#include <string>
#include <vector>

namespace tessella::sim {

/// One --vary: a key and the values it takes (YAML text each).
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

/// Parses "key=v1,v2,...": commas inside brackets or braces do not split
/// ("c=[0,0,0],[1,0,0]"). InputError quoting the argument when malformed.
SweepAxis parseSweepAxis(const std::string& argument);

struct SweepRun {
  std::string name;                 ///< "run_0000", ...
  std::vector<std::string> values;  ///< one per axis
  int replicate = 0;
  std::int64_t rng_seed = 0;
};

struct SweepPlan {
  std::string config_path;
  std::vector<std::string> sets;  ///< --set overrides applied to every run
  std::vector<SweepAxis> axes;
  int replicates = 1;
  std::vector<SweepRun> runs;  ///< every combination x replicate, last axis fastest
  std::vector<std::string> run_configs;  ///< the resolved YAML of each run
};

/// Validates every run's config (ConfigError naming the file or override and
/// the value) and returns the plan; writes nothing.
SweepPlan planSweep(const std::string& config_path, const std::vector<std::string>& sets,
                    const std::vector<SweepAxis>& axes, int replicates);

/// Writes configs/<run>.yaml, design.csv and the Snakefile into `directory`
/// (created; InputError if it already holds a sweep unless `overwrite`).
/// `tessella` is the program the workflow runs (overridable with
/// `snakemake --config tessella=PATH`).
void writeSweep(const SweepPlan& plan, const std::string& directory, const std::string& tessella, bool overwrite);

}  // namespace tessella::sim
