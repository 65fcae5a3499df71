// tessella: the command-line simulator. A thin shell over sim/: it parses
// arguments, prints, and turns errors into messages and exit codes.
//
//   tessella run CONFIG.yaml [--out DIR] [--set key.path=value ...] [--overwrite] [--quiet]
//   tessella info FILE.vtu
//   tessella schema          (the config key reference, as in docs/config.md)
//
// Exit codes: 0 success, 1 an error Tessella reports (bad config or file, a
// failed step), 2 an unexpected internal error,
// 3 (info) the tissue was read but fails validate().

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "tessella/io/vtu.hpp"
#include "tessella/sim/progress_meter.hpp"
#include "tessella/sim/run.hpp"
#include "tessella/sim/schema_docs.hpp"
#include "tessella/sim/tessella_schema.hpp"
#include "tessella/sim/tissue_summary.hpp"
#include "tessella/tissue/errors.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

const char* measureName(int dim) { return dim == 2 ? "area" : "volume"; }

int runCommand(const std::string& config_path, const std::string& out, const std::vector<std::string>& sets,
               bool overwrite, bool quiet) {
  using namespace tessella::sim;
  const auto t0 = Clock::now();
  SimulationConfig config = loadSimulationConfigFile(config_path, sets);
  if (!quiet)
    for (const std::string& note : config.config.notes()) fmt::print(stderr, "note: {}\n", note);
  if (!quiet) fmt::print(stderr, "building the tissue ({})...\n", config.config.getString("tissue.generator"));
  PreparedRun run = PreparedRun::prepare(std::move(config), RunOptions{out, overwrite});
  Simulation& sim = run.simulation();
  if (!quiet) {
    fmt::print(stderr, "tissue: {} cells ({}D, {}) in {}\n", sim.tissue().numCells(), sim.tissue().dim(),
               tessella::embeddingName(sim.tissue().embedding()),
               formatDuration(std::chrono::duration<double>(secondsSince(t0))));
    auto meter = std::make_shared<ProgressMeter>(sim.numSteps(), std::chrono::milliseconds(1000));
    sim.onStep([meter](const Simulation& s) {
      if (auto line = meter->update(s.stepsDone(), s.time(), s.tissue().numCells()))
        fmt::print(stderr, "{}\n", *line);
    });
  }
  run.execute();
  if (!quiet)
    fmt::print("wrote {} snapshots ({} steps, t = {} .. {}) to {}\nrun record: {}\n", run.snapshots(),
               sim.stepsDone(), run.config().time.start, sim.time(), run.outputDirectory(),
               run.runRecordPath());
  return 0;
}

int infoCommand(const std::string& path) {
  using namespace tessella::sim;
  const tessella::Tissue tissue = tessella::io::readTissueVtu(path);
  const TissueSummary s = summarizeTissue(tissue);
  fmt::print("file         {}\n", path);
  fmt::print("tissue       {}D, {}, time {}\n", s.dim, tessella::embeddingName(s.embedding), tissue.time());
  fmt::print("elements     {} vertices, {} edges, {} faces", s.counts[0], s.counts[1], s.counts[2]);
  if (s.dim == 3) fmt::print(", {} volumes", s.counts[3]);
  fmt::print("\ncells        {}\n", s.cells);
  fmt::print("total {:<6} {:.6g}\n", measureName(s.dim), s.total_measure);
  if (s.cell_sizes.count > 0) {
    const Distribution& d = s.cell_sizes;
    fmt::print("cell {:<7} min {:.6g}  q1 {:.6g}  median {:.6g}  q3 {:.6g}  max {:.6g}\n", measureName(s.dim),
               d.min, d.q1, d.median, d.q3, d.max);
    fmt::print("             mean {:.6g}  CV {:.4f}\n", d.mean, d.cv);
  }
  if (s.validation.ok) {
    fmt::print("validate     ok\n");
    return 0;
  }
  fmt::print("validate     FAILED: {}\n", s.validation.message);
  return 3;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Tessella: plant cell-tissue growth simulator"};
  app.set_version_flag("--version", std::string("tessella ") + tessella::sim::tessellaVersion());
  app.require_subcommand(1);

  auto* run = app.add_subcommand("run", "Build the tissue a config describes, simulate, write a ParaView series");
  std::string config_path, out;
  std::vector<std::string> sets;
  bool quiet = false, overwrite = false;
  run->add_option("config", config_path, "YAML configuration (see docs/config.md)")->required();
  run->add_option("--out,-o", out, "Output directory (default: output.directory, else runs/<config name>)");
  run->add_option("--set,-s", sets, "Override a key: --set tissue.voronoi.count=50 (value parsed as YAML)")
      ->take_all()
      ->allow_extra_args(false);
  run->add_flag("--overwrite", overwrite, "Replace a run already in the output directory");
  run->add_flag("--quiet,-q", quiet, "Print nothing but errors");

  auto* info = app.add_subcommand("info", "Summarise a tissue snapshot (.vtu): counts, sizes, validity");
  std::string vtu_path;
  info->add_option("file", vtu_path, "Snapshot written by tessella run")->required();

  app.add_subcommand("schema", "Print the configuration key reference (Markdown, as in docs/config.md)");

  CLI11_PARSE(app, argc, argv);
  try {
    if (run->parsed()) return runCommand(config_path, out, sets, overwrite, quiet);
    if (info->parsed()) return infoCommand(vtu_path);
    fmt::print("{}", tessella::sim::schemaReferenceMarkdown(tessella::sim::tessellaSchema()));
    return 0;
  } catch (const tessella::Error& e) {  // bad input, or a stage that failed on it
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "internal error: {}\n", e.what());
    return 2;
  }
}
