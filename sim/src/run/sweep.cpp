// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/run/sweep.hpp"

#include <cstdio>
#include <filesystem>

#include "tessella/io/text_file.hpp"
#include "tessella/sim/config/config_error.hpp"
#include "tessella/sim/config/config_loader.hpp"
#include "tessella/sim/run/run_record.hpp"
#include "tessella/sim/sections/tessella_schema.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::sim {

namespace fs = std::filesystem;

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// A CSV field, quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// The workflow: one job per run (skipped when its `finished` marker exists,
// so a rerun only does what is missing), then one job collecting the last row
// of every run's stats.csv next to its design row.
std::string snakefile(const std::string& tessella) {
  std::string quoted;
  for (char c : tessella) quoted += (c == '\\' || c == '"') ? std::string("\\") + c : std::string(1, c);
  return R"(# A Tessella parameter sweep, written by `tessella sweep` (docs/sweeps.md).
#   snakemake -j 2                              # here, two runs at a time
#   snakemake -j 100 --profile MY_CLUSTER       # a cluster (Slurm, ...): the workflow is unchanged
#   snakemake -j 2 --config tessella=/path/to/tessella
# A run that stopped half way is rerun from the start; finished runs are kept.
import csv

TESSELLA = config.get("tessella", ")" +
         quoted + R"(")
with open("design.csv", newline="") as f:
    DESIGN = list(csv.DictReader(f))
RUNS = [row["run"] for row in DESIGN]


rule all:
    input:
        "sweep.csv",


rule run:
    input:
        "configs/{run}.yaml",
    output:
        "runs/{run}/finished",
    log:
        "logs/{run}.log",
    # One core per run unless `--set-threads run=N`: Snakemake runs -j runs at once, and
    # OpenMP would otherwise start a thread per core in each of them.
    threads: 1
    shell:
        'OMP_NUM_THREADS={threads} "{TESSELLA}" run {input} --out runs/{wildcards.run} --overwrite --quiet'
        ' > {log} 2>&1 && touch {output}'


rule collect:
    input:
        expand("runs/{run}/finished", run=RUNS),
    output:
        "sweep.csv",
    run:
        rows, stats_columns = [], []
        for row in DESIGN:
            with open(f"runs/{row['run']}/stats.csv", newline="") as f:
                records = list(csv.DictReader(f))
            if not records:
                raise ValueError(f"runs/{row['run']}/stats.csv has no row")
            final = records[-1]
            stats_columns += [k for k in final if k not in stats_columns]
            rows.append({**row, **final})
        with open(output[0], "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(DESIGN[0].keys()) + stats_columns)
            writer.writeheader()
            writer.writerows(rows)
)";
}

}  // namespace

SweepAxis parseSweepAxis(const std::string& argument) {
  const auto eq = argument.find('=');
  const auto bad = [&](const std::string& why) {
    return InputError("--vary '" + argument + "': " + why + " (expected key=value1,value2,...)");
  };
  if (eq == std::string::npos) throw bad("no '='");
  SweepAxis axis;
  axis.key = trim(argument.substr(0, eq));
  if (axis.key.empty()) throw bad("no key");
  const std::string list = argument.substr(eq + 1);
  int depth = 0;
  std::string current;
  for (char c : list) {
    if (c == '[' || c == '{') ++depth;
    if (c == ']' || c == '}') --depth;
    if (depth < 0) throw bad("unbalanced brackets");
    if (c == ',' && depth == 0) {
      axis.values.push_back(trim(current));
      current.clear();
    } else {
      current += c;
    }
  }
  if (depth != 0) throw bad("unbalanced brackets");
  axis.values.push_back(trim(current));
  for (const auto& v : axis.values)
    if (v.empty()) throw bad("an empty value");
  for (std::size_t i = 0; i < axis.values.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (axis.values[i] == axis.values[j]) throw bad("the value '" + axis.values[i] + "' is given twice");
  return axis;
}

SweepPlan planSweep(const std::string& config_path, const std::vector<std::string>& sets,
                    const std::vector<SweepAxis>& axes, int replicates) {
  if (replicates < 1) throw InputError("--replicates must be >= 1, got " + std::to_string(replicates));
  for (std::size_t i = 0; i < axes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (axes[i].key == axes[j].key) throw InputError("--vary " + axes[i].key + " is given twice");
  SweepPlan plan{config_path, sets, axes, replicates, {}, {}};
  // The base seed: the config's own (with the --set overrides), else 1.
  const Config base = loadConfigFile(config_path, sets, tessellaSchema());
  const std::int64_t seed = base.has("rng_seed") ? base.getInt("rng_seed") : 1;

  std::size_t combinations = 1;
  for (const auto& a : axes) combinations *= a.values.size();
  if (combinations * static_cast<std::size_t>(replicates) > 100000)
    throw InputError("the sweep has " + std::to_string(combinations * replicates) +
                     " runs; more than 100000 is refused (split it)");
  for (std::size_t k = 0; k < combinations; ++k) {
    std::vector<std::string> values(axes.size());
    std::size_t rest = k;
    for (std::size_t a = axes.size(); a-- > 0;) {  // the last axis varies fastest
      values[a] = axes[a].values[rest % axes[a].values.size()];
      rest /= axes[a].values.size();
    }
    std::vector<std::string> overrides = sets;
    for (std::size_t a = 0; a < axes.size(); ++a) overrides.push_back(axes[a].key + "=" + values[a]);
    for (int r = 0; r < replicates; ++r) {
      SweepRun run;
      char name[32];
      std::snprintf(name, sizeof name, "run_%04zu", plan.runs.size());
      run.name = name;
      run.values = values;
      run.replicate = r;
      run.rng_seed = seed + r;
      std::vector<std::string> with_seed = overrides;
      with_seed.push_back("rng_seed=" + std::to_string(run.rng_seed));
      const Config config = loadConfigFile(config_path, with_seed, tessellaSchema());
      // A key the config ignores (growth.uniform.rate without growth.field:
      // uniform) would make a sweep of identical runs.
      for (const auto& a : axes)
        if (!config.isActive(a.key))
          throw InputError("--vary " + a.key + ": " + config_path + " ignores this key (it applies only under " +
                           "other settings, e.g. the generator, field or rule its section belongs to); set those " +
                           "with --set or vary an active key");
      plan.run_configs.push_back(resolvedConfigYaml(config));
      plan.runs.push_back(std::move(run));
    }
  }
  return plan;
}

void writeSweep(const SweepPlan& plan, const std::string& directory, const std::string& tessella, bool overwrite) {
  if (directory.empty()) throw InputError("the sweep directory must not be empty");
  const fs::path dir = directory;
  std::error_code ec;
  if (fs::exists(dir / "Snakefile", ec) && !overwrite)
    throw InputError("'" + directory + "' already holds a sweep (Snakefile); choose another --out or pass --overwrite");
  fs::create_directories(dir / "configs", ec);
  if (ec) throw InputError("cannot create the sweep directory '" + directory + "': " + ec.message());
  std::string design = "run,replicate,rng_seed";
  for (const auto& a : plan.axes) design += "," + csvField(a.key);
  design += "\n";
  for (std::size_t i = 0; i < plan.runs.size(); ++i) {
    const SweepRun& r = plan.runs[i];
    io::writeTextFile((dir / "configs" / (r.name + ".yaml")).string(), plan.run_configs[i]);
    design += r.name + "," + std::to_string(r.replicate) + "," + std::to_string(r.rng_seed);
    for (const auto& v : r.values) design += "," + csvField(v);
    design += "\n";
  }
  io::writeTextFile((dir / "design.csv").string(), design);
  // The Snakefile last: its presence marks a complete sweep directory.
  io::writeTextFile((dir / "Snakefile").string(), snakefile(tessella));
}

}  // namespace tessella::sim
