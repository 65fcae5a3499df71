// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/render/run_report.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>

#include "tessella/io/pvd.hpp"
#include "tessella/io/text_file.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/render/series_pictures.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/parameters.hpp"

extern char** environ;

namespace tessella::render {

namespace fs = std::filesystem;

namespace {

// Evenly spaced indices into n items, at most m of them, the last always.
std::vector<std::size_t> spread(std::size_t n, std::size_t m) {
  std::vector<std::size_t> out;
  if (n == 0 || m == 0) return out;
  if (n <= m) {
    for (std::size_t i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  for (std::size_t k = 0; k < m; ++k) out.push_back(k * (n - 1) / (m - 1 == 0 ? 1 : m - 1));
  return out;
}

std::string findScript(const std::string& given) {
  if (!given.empty()) return given;
  if (const char* env = std::getenv("TESSELLA_REPORT_SCRIPT")) return env;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = self.parent_path().parent_path() / "share" / "tessella" / "tessella_report.py";
    if (fs::exists(installed, ec)) return installed.string();
  }
  return TESSELLA_REPORT_SCRIPT_SOURCE;  // the source tree's copy (a build-tree program)
}

// Runs argv (no shell) with its output into `log`; the exit status, or -1.
int runLogged(const std::vector<std::string>& argv, const std::string& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0].c_str(), &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

RunReport writeRunReport(const std::string& run_dir, const RunReportOptions& options) {
  const fs::path dir = run_dir;
  for (const char* needed : {"tissue.pvd", "stats.csv", "run.yaml"})
    if (!fs::exists(dir / needed))
      throw InputError("'" + run_dir + "' is not a run directory written by tessella run: it has no " + needed);
  const fs::path out = dir / "report";
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw InputError("cannot create '" + out.string() + "': " + ec.message());

  const std::vector<io::PvdEntry> series = io::readPvdFile((dir / "tissue.pvd").string());
  if (series.empty()) throw InputError("'" + (dir / "tissue.pvd").string() + "' lists no snapshot");
  RunReport report;

  // One row per cell per snapshot read; a division is a pair of sisters (same
  // parent, born after the previous snapshot read): its wall's normal is
  // close to the line between the sisters' centroids.
  std::string cells = "snapshot,time,lineage_id,parent_id,birth_time,size,x,y,z\n";
  std::string divisions = "time,parent_id,angle_deg,nx,ny,nz\n";
  double previous_time = -std::numeric_limits<double>::infinity();
  for (std::size_t i : spread(series.size(), static_cast<std::size_t>(std::max(options.max_snapshots, 2)))) {
    const std::string path = (dir / series[i].file).string();
    const Tissue t = io::readTissueVtu(path);
    std::map<std::int64_t, std::vector<Vec3>> sisters;
    char row[256];
    for (CellId c : t.cells()) {
      const Vec3 x = cellCentroid(t, c);
      std::snprintf(row, sizeof row, "%zu,%.17g,%lld,%lld,%.17g,%.17g,%.17g,%.17g,%.17g\n", i, t.time(),
                    static_cast<long long>(t.lineageId(c)), static_cast<long long>(t.parentId(c)), t.birthTime(c),
                    cellMeasure(t, c), x.x(), x.y(), x.z());
      cells += row;
      if (t.parentId(c) >= 0 && t.birthTime(c) > previous_time) sisters[t.parentId(c)].push_back(x);
    }
    for (const auto& [parent, centroids] : sisters) {
      if (centroids.size() != 2) continue;  // a sister divided again before this snapshot
      const Vec3 n = (centroids[1] - centroids[0]).normalized();
      // The wall's orientation in the xy plane, in [0, 180): the angle of the
      // wall itself, perpendicular to the line between the sisters.
      double angle = std::atan2(n.y(), n.x()) * 180.0 / std::numbers::pi + 90.0;
      angle = std::fmod(std::fmod(angle, 180.0) + 180.0, 180.0);
      std::snprintf(row, sizeof row, "%.17g,%lld,%.6f,%.9g,%.9g,%.9g\n", t.time(), static_cast<long long>(parent),
                    angle, n.x(), n.y(), n.z());
      divisions += row;
      ++report.divisions;
    }
    previous_time = t.time();
    ++report.snapshots;
  }
  io::writeTextFile((out / "cells.csv").string(), cells);
  io::writeTextFile((out / "divisions.csv").string(), divisions);

  SeriesPictureOptions pictures;
  pictures.picture.property = options.property;
  pictures.picture.width = 640, pictures.picture.height = 480;
  pictures.every = std::max<int>(1, static_cast<int>((series.size() + options.max_frames - 1) / options.max_frames));
  pictures.movie = false;
  fs::remove_all(out / "frames", ec);  // a previous report's frames
  report.frames = static_cast<int>(writeSeriesPictures(run_dir, (out / "frames").string(), pictures).frames.size());

  const std::string script = findScript(options.script);
  if (!fs::exists(script)) throw InputError("the report script '" + script + "' is missing (set TESSELLA_REPORT_SCRIPT)");
  const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string log = (out / "report.log").string();
  const int status = runLogged({python, script, run_dir}, log);
  if (status != 0) {
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.size() > 2000) text = "..." + text.substr(text.size() - 2000);
    throw InputError("the report script " + script + " failed (exit status " + std::to_string(status) + "; " + log +
                     "):\n" + text);
  }
  report.html = (dir / "report.html").string();
  return report;
}

}  // namespace tessella::render
