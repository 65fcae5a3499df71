// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// tessella: the command-line simulator. A thin shell over sim/: it parses
// arguments, prints, and turns errors into messages and exit codes.
//
//   tessella run CONFIG.yaml [--out DIR] [--set key.path=value ...] [--overwrite] [--quiet]
//   tessella run --resume RUN_DIR [--quiet]
//   tessella info FILE.vtu
//   tessella mesh SNAPSHOT.vtu --out MESH.vtu [--walls WALLS.vtu] [--size H] [--min-angle A] [--max-volume V]
//                 [--volume-method cell_by_cell|whole_tissue] [--max-elements N] [--config CFG.yaml]
//   tessella import FILE --out TISSUE.vtu [--format F] [--scale S] [--simplify TOL] [--repair]
//                   [--label-array NAME]
//                   [--voxel-size X,Y] [--background L,..] [--drop-labels L,..] [--min-cell-size N]
//                   [--small-cells drop|merge] [--crop X0,Y0,X1,Y1[,..]] [--keep-pieces]   (label images)
//   tessella export SNAPSHOT.vtu --out FILE.ply [--binary]   (cell-complex PLY, docs/import.md)
//   tessella render RUN_DIR|SERIES.pvd|SNAPSHOT.vtu [--property NAME] [--out DIR] [--size WxH] [--every N]
//                   [--view X,Y,Z] [--range LOW,HIGH] [--no-movie]
//   tessella sweep CONFIG.yaml --vary KEY=V1,V2,... [--vary ...] [--replicates N] [--set ...] --out DIR [--overwrite]
//   tessella report RUN_DIR [--property NAME]   (RUN_DIR/report.html: plots, frames, config)
//   tessella schema          (the config key reference, as in docs/config.md)
//
// Exit codes: 0 success, 1 an error Tessella reports (bad config or file, a
// failed step), 2 an unexpected internal error,
// 3 (info, import) the tissue was read but fails validate() (import then
// writes nothing),
// 130 / 143 (run) stopped by SIGINT / SIGTERM: the run ends after the step in
// progress, with every file written so far complete (a second signal ends it
// at once).

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessella/io/cell_complex_ply.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/mesh_vtu.hpp"
#include "tessella/io/output_file.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/mesh/mesh_agreement.hpp"
#include "tessella/mesh/mesh_options.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/render/run_report.hpp"
#include "tessella/render/series_pictures.hpp"
#include "tessella/sim/config/config_loader.hpp"
#include "tessella/sim/config/schema_docs.hpp"
#include "tessella/sim/run/progress_meter.hpp"
#include "tessella/sim/run/run.hpp"
#include "tessella/sim/run/sweep.hpp"
#include "tessella/sim/run/tissue_summary.hpp"
#include "tessella/sim/sections/mesh_section.hpp"
#include "tessella/sim/sections/tessella_schema.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/tissue.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

const char* measureName(int dim) { return dim == 2 ? "area" : "volume"; }

// SIGINT / SIGTERM during `run`: the handler only records the signal; the
// simulation checks the flag between steps (Simulation::setStopFlag).
static_assert(std::atomic<bool>::is_always_lock_free, "the stop flag is set from a signal handler");
std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void onStopSignal(int signal) {
  if (g_stop_signal == 0) g_stop_signal = signal;
  g_stop.store(true);
}

void installStopHandlers() {
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: a second signal of the same kind ends the program at once.
  action.sa_flags = SA_RESTART | SA_RESETHAND;
  for (const int signal : {SIGINT, SIGTERM}) {
    struct sigaction previous {};
    sigaction(signal, nullptr, &previous);
    if (previous.sa_handler == SIG_IGN) continue;  // e.g. a background job of a script: stays ignored
    sigaction(signal, &action, nullptr);
  }
}

int reportInterrupted(const tessella::sim::PreparedRun& run) {
  const int signal = g_stop_signal;
  const char* name = signal == SIGTERM ? "SIGTERM" : "SIGINT";
  const tessella::sim::Simulation& sim = run.simulation();
  if (run.seriesPath().empty()) {
    fmt::print(stderr, "interrupted ({}) before the run started: nothing was written\n", name);
  } else {
    fmt::print(stderr, "interrupted ({}) after step {}/{} (t = {}): saved {} complete snapshots, listed in {}",
               name, sim.stepsDone(), sim.numSteps(), sim.time(), run.snapshots(), run.seriesPath());
    if (run.meshSnapshots() > 0) fmt::print(stderr, ", and {} mesh snapshots", run.meshSnapshots());
    fmt::print(stderr, "; run record {}\n", run.runRecordPath());
  }
  return 128 + signal;
}

tessella::sim::PreparedRun prepareRun(const std::string& config_path, const std::optional<std::string>& out,
                                      const std::vector<std::string>& sets, bool overwrite, bool quiet) {
  using namespace tessella::sim;
  SimulationConfig config = loadSimulationConfigFile(config_path, sets);
  if (!quiet)
    for (const std::string& note : config.config.notes()) fmt::print(stderr, "note: {}\n", note);
  if (!quiet) fmt::print(stderr, "building the tissue ({})...\n", config.config.getString("tissue.generator"));
  return PreparedRun::prepare(std::move(config), RunOptions{out, overwrite});
}

// `resume` (RUN_DIR) continues an interrupted run in place instead of
// starting the config's.
int runCommand(const std::string& config_path, const std::string& resume, const std::optional<std::string>& out,
               const std::vector<std::string>& sets, bool overwrite, bool quiet) {
  using namespace tessella::sim;
  const auto t0 = Clock::now();
  installStopHandlers();
  if (resume.empty() == config_path.empty())
    throw tessella::InputError("tessella run takes a CONFIG.yaml or --resume RUN_DIR (one of the two)");
  PreparedRun run = resume.empty() ? prepareRun(config_path, out, sets, overwrite, quiet) : PreparedRun::resume(resume);
  Simulation& sim = run.simulation();
  if (!quiet && !resume.empty())
    fmt::print(stderr, "resuming from {} (step {}, t = {})\n", run.resumedFrom(), sim.clockStep(), sim.time());
  sim.setStopFlag(&g_stop);
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
  if (run.interrupted()) return reportInterrupted(run);
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
  fmt::print("file         {}\n{}", path, formatTissueSummary(s, tissue.time()));
  return s.validation.ok ? 0 : 3;
}

struct ImportArgs {
  std::string file, out, format = "auto", label_array;
  double scale = 1.0, simplify = 0.0;
  bool repair = false;
  tessella::io::LabelImageOptions image;
};

int importCommand(const ImportArgs& a) {
  using namespace tessella;
  io::ImportOptions options{a.format, a.scale, a.simplify, a.repair, a.label_array};
  options.image = a.image;
  const io::ImportResult r = io::importTissue(a.file, options);
  const sim::TissueSummary s = sim::summarizeTissue(r.tissue);
  fmt::print("{}", sim::formatImportSummary(r.report, s, r.tissue.time()));
  if (!s.validation.ok) {
    fmt::print(stderr, "error: not writing {}: the imported tissue fails validate()\n", a.out);
    return 3;
  }
  io::writeTissueVtu(r.tissue, a.out);  // atomic: no partial file on failure
  fmt::print("wrote        {}\n", a.out);
  return 0;
}

struct ExportArgs {
  std::string snapshot, out;
  bool binary = false;
};

int exportCommand(const ExportArgs& a) {
  using namespace tessella;
  io::checkOutputFile(a.out, "--out");
  const Tissue tissue = io::readTissueVtu(a.snapshot);
  const io::CellComplexPlyInfo info = io::writeCellComplexPly(tissue, a.out, io::CellComplexPlyOptions{a.binary});
  fmt::print("file         {}\ntissue       {}D, {}, {} cells\n", a.snapshot, tissue.dim(),
             embeddingName(tissue.embedding()), tissue.numCells());
  fmt::print("wrote        {} (cell-complex PLY, {}: {} vertices, {} edges, {} faces, {} volumes; volume labels "
             "from {})\n",
             a.out, a.binary ? "binary" : "ASCII", info.vertices, info.edges, info.faces, info.volumes,
             info.label_source);
  return 0;
}

struct MeshArgs {
  std::string snapshot, out, walls_out, config;
  std::optional<double> size, min_angle, max_volume;
  std::optional<std::size_t> max_elements;
  std::optional<double> cell_time_limit, time_limit;
  std::optional<std::string> volume_method;
};

int meshCommand(const MeshArgs& a) {
  using namespace tessella;
  const auto t0 = Clock::now();
  // Options: MeshOptions defaults < the config's mesh: section < flags.
  mesh::MeshOptions options;
  if (!a.config.empty())
    options = sim::meshOptionsFromConfig(sim::loadConfigFile(a.config, {}, sim::tessellaSchema()));
  if (a.size) options.max_edge_length = *a.size;
  if (a.min_angle) options.min_angle_degrees = *a.min_angle;
  if (a.max_volume) options.max_volume = *a.max_volume;
  if (a.volume_method) options.volume_method = tessella::mesh::volumeMethods().parse(*a.volume_method);
  if (a.max_elements) options.max_elements = *a.max_elements;
  if (a.cell_time_limit) options.cell_time_limit = *a.cell_time_limit;
  if (a.time_limit) options.time_limit = *a.time_limit;
  mesh::validateMeshOptions(options);  // before reading: a bad flag fails fast
  io::checkOutputFile(a.out, "--out");  // every output, before meshing or writing any of them
  if (!a.walls_out.empty()) io::checkOutputFile(a.walls_out, "--walls");

  const Tissue tissue = io::readTissueVtu(a.snapshot);
  const double t_read = secondsSince(t0);
  const auto t1 = Clock::now();
  const mesh::FeMesh mesh = mesh::meshTissue(tissue, options);
  const double t_mesh = secondsSince(t1);

  const mesh::MeshAgreement agreement = mesh::meshAgreement(tissue, mesh);

  io::writeFeMeshVtu(mesh, a.out);  // atomic: no partial file on failure
  if (!a.walls_out.empty()) io::writeWallFacetsVtu(mesh, a.walls_out);

  const char* elements = mesh.dim == 2 ? "triangles" : "tetrahedra";
  fmt::print("tissue       {} cells ({}D, {}) from {} (read in {:.3f} s)\n", tissue.numCells(), tissue.dim(),
             embeddingName(tissue.embedding()), a.snapshot, t_read);
  fmt::print("options      min_angle {} deg, max_edge_length {}, max_volume {}, radius_edge_ratio {}{}\n",
             options.min_angle_degrees, options.max_edge_length, options.max_volume, options.radius_edge_ratio,
             tissue.dim() != 3 ? "" : ", " + tessella::mesh::volumeMethods().name(options.volume_method));
  fmt::print("mesh         {} nodes, {} {}, {} wall facets\n", mesh.numNodes(), mesh.numElements(), elements,
             mesh.numWallFacets());
  fmt::print("time         {:.3f} s ({:.0f} elements/s)\n", t_mesh, mesh.numElements() / std::max(t_mesh, 1e-9));
  fmt::print("cell {:<7} worst relative difference {:.3g} (cell {}), total {:.3g}\n", measureName(tissue.dim()),
             agreement.worst_cell_difference, agreement.worst_cell, agreement.total_difference);
  fmt::print("wrote        {}", a.out);
  if (!a.walls_out.empty()) fmt::print(" and {}", a.walls_out);
  fmt::print("\n");
  return 0;
}

struct RenderArgs {
  std::string source, out, property, size = "800x800";
  int every = 1;
  std::vector<double> view = {0, 0, 1}, range;
  bool no_movie = false;
};

int renderCommand(const RenderArgs& a) {
  using namespace tessella;
  render::SeriesPictureOptions o;
  o.picture.property = a.property;
  const auto x = a.size.find('x');
  try {
    std::size_t used_w = 0, used_h = 0;
    o.picture.width = std::stoi(a.size.substr(0, x), &used_w);
    o.picture.height = std::stoi(a.size.substr(x + 1), &used_h);
    if (x == std::string::npos || used_w != x || used_h != a.size.size() - x - 1) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw InputError("--size: expected WIDTHxHEIGHT in pixels (e.g. 800x600), got '" + a.size + "'");
  }
  o.picture.view = Vec3(a.view[0], a.view[1], a.view[2]);
  if (!a.range.empty()) o.picture.range = render::ColourRange{a.range[0], a.range[1]};
  o.every = a.every;
  o.movie = !a.no_movie;
  namespace fs = std::filesystem;
  std::string out = a.out;
  if (out.empty())  // beside the run: RUN_DIR/frames, or SNAPSHOT_frames
    out = fs::is_directory(a.source) ? (fs::path(a.source) / "frames").string()
                                     : (fs::path(a.source).parent_path() / (fs::path(a.source).stem().string() + "_frames")).string();
  const render::SeriesPictures made = render::writeSeriesPictures(a.source, out, o);
  fmt::print("wrote        {} frame{} to {}\n", made.frames.size(), made.frames.size() == 1 ? "" : "s", out);
  if (!a.property.empty())
    fmt::print("colours      {} from {} to {} (viridis)\n", a.property, formatNumber(made.range.low),
               formatNumber(made.range.high));
  if (!made.movie.empty()) fmt::print("movie        {}\n", made.movie);
  if (!made.movie_note.empty() && o.movie && made.frames.size() > 1) fmt::print("movie        {}\n", made.movie_note);
  return 0;
}

struct SweepArgs {
  std::string config, out;
  std::vector<std::string> vary, sets;
  int replicates = 1;
  bool overwrite = false;
};

int sweepCommand(const SweepArgs& a) {
  using namespace tessella;
  std::vector<sim::SweepAxis> axes;
  for (const auto& v : a.vary) axes.push_back(sim::parseSweepAxis(v));
  const sim::SweepPlan plan = sim::planSweep(a.config, a.sets, axes, a.replicates);
  std::error_code ec;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
  sim::writeSweep(plan, a.out, ec ? std::string("tessella") : self, a.overwrite);
  fmt::print("wrote        {} run configs, design.csv and a Snakefile to {}\n", plan.runs.size(), a.out);
  fmt::print("run them     cd {} && snakemake -j 2   (results: sweep.csv)\n", a.out);
  return 0;
}

int reportCommand(const std::string& run_dir, const std::string& property) {
  tessella::render::RunReportOptions o;
  if (!property.empty()) o.property = property;
  const tessella::render::RunReport r = tessella::render::writeRunReport(run_dir, o);
  fmt::print("read         {} snapshots ({} divisions between them), drew {} frames\n", r.snapshots, r.divisions,
             r.frames);
  fmt::print("wrote        {}\n", r.html);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Tessella: plant cell-tissue growth simulator"};
  app.set_version_flag("--version", std::string("tessella ") + tessella::sim::tessellaVersion());
  app.require_subcommand(1);

  auto* run = app.add_subcommand("run", "Build the tissue a config describes, simulate, write a ParaView series");
  std::string config_path;
  std::optional<std::string> out;  // given but empty (--out '') is refused, not the default
  std::vector<std::string> sets;
  bool quiet = false, overwrite = false;
  std::string resume_dir;
  auto* config_option = run->add_option("config", config_path, "YAML configuration (see docs/config.md)");
  auto* resume_option = run->add_option(
      "--resume", resume_dir,
      "Continue the interrupted run in RUN_DIR in place, from its last complete snapshot (instead of a config)");
  auto* out_option =
      run->add_option("--out,-o", out, "Output directory (default: output.directory, else runs/<config name>)");
  auto* set_option =
      run->add_option("--set,-s", sets, "Override a key: --set tissue.voronoi.count=50 (value parsed as YAML)")
          ->take_all()
          ->allow_extra_args(false);
  auto* overwrite_option = run->add_flag("--overwrite", overwrite, "Replace a run already in the output directory");
  resume_option->excludes(config_option)->excludes(out_option)->excludes(set_option)->excludes(overwrite_option);
  run->callback([&] {
    if (config_path.empty() && resume_dir.empty())
      throw CLI::RequiredError("config (or --resume RUN_DIR)");
  });
  run->add_flag("--quiet,-q", quiet, "Print nothing but errors");

  auto* info = app.add_subcommand("info", "Summarise a tissue snapshot (.vtu): counts, sizes, validity");
  std::string vtu_path;
  info->add_option("file", vtu_path, "Snapshot written by tessella run")->required();

  auto* mesh = app.add_subcommand("mesh", "Mesh a tissue snapshot (.vtu) into triangles or tetrahedra (.vtu)");
  MeshArgs mesh_args;
  mesh->add_option("snapshot", mesh_args.snapshot, "Tissue snapshot written by tessella run")->required();
  mesh->add_option("--out,-o", mesh_args.out, "Mesh file to write (.vtu, with cell_id per element)")->required();
  mesh->add_option("--walls", mesh_args.walls_out, "Also write the wall facets (.vtu, with wall_id per facet)");
  mesh->add_option("--config,-c", mesh_args.config, "Take the mesh: section of this config (flags override it)");
  mesh->add_option("--size", mesh_args.size, "Longest triangle edge (mesh.max_edge_length; 0 = none)");
  mesh->add_option("--min-angle", mesh_args.min_angle, "Smallest triangle angle in degrees (mesh.min_angle)");
  mesh->add_option("--max-volume", mesh_args.max_volume, "Largest tetrahedron volume (mesh.max_volume; 0 = none)");
  mesh->add_option("--max-elements", mesh_args.max_elements,
                   "Refuse a mesh estimated above this many elements (mesh.max_elements; default " +
                       std::to_string(tessella::mesh::kDefaultMaxElements) + ", 0 = no limit)");
  mesh->add_option("--cell-time-limit", mesh_args.cell_time_limit,
                   "3D: seconds one cell's TetGen tries may take together (mesh.cell_time_limit; 0 = none)");
  mesh->add_option("--time-limit", mesh_args.time_limit,
                   "3D: seconds all TetGen runs of the mesh may take together (mesh.time_limit; 0 = none)");
  mesh->add_option("--volume-method", mesh_args.volume_method, "3D: cell_by_cell or whole_tissue (mesh.volume_method)")
      ->check(CLI::IsMember(tessella::mesh::volumeMethods().names()));

  auto* import = app.add_subcommand(
      "import", "Import a segmented tissue (MorphoGraphX PLY, ...), summarise it, write a snapshot (.vtu)");
  ImportArgs import_args;
  import->add_option("file", import_args.file, "The file to import (see docs/import.md)")->required();
  import->add_option("--out,-o", import_args.out, "Snapshot to write (.vtu)")->required();
  import->add_option("--format,-f", import_args.format, "auto (from the extension and contents) or a format name")
      ->check(CLI::IsMember(tessella::io::importFormatNames()));
  import->add_option("--scale", import_args.scale, "Multiply every position by this (unit conversion)");
  import->add_option("--simplify", import_args.simplify,
                     "Simplify wall polylines between junctions to this tolerance (0 = keep every vertex; label "
                     "images: in pixels)");
  import->add_flag("--repair", import_args.repair, "Repair harmless defects (a one-triangle sliver), each reported");
  import->add_option("--label-array", import_args.label_array,
                     "labelled_mesh, labelled_vtu: the face property / cell-data array (OBJ: g, o or usemtl) holding "
                     "each face's cell label; A,B for the cells on either side (default: label, cell_label, cell_id)");
  import->add_option("--voxel-size", import_args.image.voxel_size,
                     "Label images: pixel size X,Y (or X,Y,Z), overriding the file's")
      ->delimiter(',');
  import->add_option("--background", import_args.image.background,
                     "Label images: the labels that are no cell (default 0,1)")
      ->delimiter(',');
  import->add_option("--drop-labels", import_args.image.drop_labels, "Label images: labels to drop (made background)")
      ->delimiter(',');
  import->add_option("--min-cell-size", import_args.image.min_cell_size,
                     "Label images: labels with fewer pixels are dropped or merged (--small-cells)");
  import->add_option("--small-cells", import_args.image.small_cells,
                     "Label images: drop (default) or merge (into the neighbour sharing the longest wall)")
      ->check(CLI::IsMember({"drop", "merge"}));
  import->add_option("--crop", import_args.image.crop,
                     "Label images: only the pixels X0 <= i < X1, Y0 <= j < Y1 (3D: X0,Y0,Z0,X1,Y1,Z1)")
      ->delimiter(',');
  import->add_flag("--keep-pieces", import_args.image.keep_pieces,
                   "Label images: a label in disconnected pieces becomes one cell per piece (else an error)");

  auto* export_ = app.add_subcommand(
      "export", "Write a tissue snapshot (.vtu) as a cell-complex PLY file (OpenAlea property topomesh)");
  ExportArgs export_args;
  export_->add_option("snapshot", export_args.snapshot, "Tissue snapshot (.vtu) to convert")->required();
  export_->add_option("--out,-o", export_args.out, "Cell-complex PLY file to write (see docs/import.md)")->required();
  export_->add_flag("--binary", export_args.binary, "binary_little_endian instead of ASCII");

  auto* render = app.add_subcommand(
      "render", "Draw the snapshots of a run as PNG frames coloured by a cell property (and a movie with ffmpeg)");
  RenderArgs render_args;
  render->add_option("source", render_args.source, "Run directory (its tissue.pvd), a .pvd series or a .vtu snapshot")
      ->required();
  render->add_option("--property,-p", render_args.property,
                     "Cell property to colour by (any number per cell; 'size' is the area or volume)");
  render->add_option("--out,-o", render_args.out, "Directory for the frames (default: RUN_DIR/frames)");
  render->add_option("--size", render_args.size, "Picture size in pixels, WIDTHxHEIGHT (default 800x800)");
  render->add_option("--every", render_args.every, "Draw every N-th snapshot (and the last)")->check(CLI::PositiveNumber);
  render->add_option("--view", render_args.view, "Direction towards the viewer (default 0,0,1: from above)")
      ->expected(3)
      ->delimiter(',');
  render->add_option("--range", render_args.range, "Colour range LOW,HIGH (default: the series' own range)")
      ->expected(2)
      ->delimiter(',');
  render->add_flag("--no-movie", render_args.no_movie, "Do not encode movie.mp4 even if ffmpeg is installed");

  auto* sweep = app.add_subcommand(
      "sweep", "Write a parameter sweep: one config per combination and replicate, and a Snakemake workflow");
  SweepArgs sweep_args;
  sweep->add_option("config", sweep_args.config, "YAML configuration the runs start from")->required();
  sweep->add_option("--vary", sweep_args.vary, "A key and its values: --vary division.size=1.5,2 (repeatable)")
      ->required()
      ->take_all()
      ->allow_extra_args(false);
  sweep->add_option("--replicates,-r", sweep_args.replicates, "Runs per combination, seeds rng_seed, rng_seed + 1, ...")
      ->check(CLI::PositiveNumber);
  sweep->add_option("--set,-s", sweep_args.sets, "Override a key in every run: --set time.end=5")
      ->take_all()
      ->allow_extra_args(false);
  sweep->add_option("--out,-o", sweep_args.out, "Sweep directory to write")->required();
  sweep->add_flag("--overwrite", sweep_args.overwrite, "Replace a sweep already in the directory");

  auto* report = app.add_subcommand(
      "report", "Write RUN_DIR/report.html: cell counts, sizes, division orientations, field totals, frames, config");
  std::string report_dir, report_property;
  report->add_option("run", report_dir, "Run directory written by tessella run")->required();
  report->add_option("--property,-p", report_property, "Cell property the frames are coloured by (default: size)");

  app.add_subcommand("schema", "Print the configuration key reference (Markdown, as in docs/config.md)");

  CLI11_PARSE(app, argc, argv);
  try {
    if (run->parsed()) return runCommand(config_path, resume_dir, out, sets, overwrite, quiet);
    if (info->parsed()) return infoCommand(vtu_path);
    if (mesh->parsed()) return meshCommand(mesh_args);
    if (import->parsed()) return importCommand(import_args);
    if (export_->parsed()) return exportCommand(export_args);
    if (render->parsed()) return renderCommand(render_args);
    if (sweep->parsed()) return sweepCommand(sweep_args);
    if (report->parsed()) return reportCommand(report_dir, report_property);
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
