// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/render/series_pictures.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "tessella/io/pvd.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

extern char** environ;

namespace tessella::render {

namespace fs = std::filesystem;

namespace {

struct Snapshot {
  std::string path;
  double time = 0;  ///< as the series lists it
};

// The snapshots of a run directory (its tissue.pvd), a .pvd file or one .vtu.
std::vector<Snapshot> snapshotsOf(const std::string& source) {
  fs::path pvd = source;
  std::error_code ec;
  if (fs::is_directory(source, ec)) {
    pvd = fs::path(source) / "tissue.pvd";
    if (!fs::exists(pvd, ec))
      throw InputError("'" + source + "' is a directory without a tissue series (no tissue.pvd): give a run directory "
                       "written by tessella run, a .pvd file or a .vtu snapshot");
  } else if (!fs::exists(source, ec)) {
    throw InputError("cannot render '" + source + "': no such file or directory");
  }
  if (pvd.extension() == ".vtu") return {{pvd.string(), 0.0}};
  if (pvd.extension() != ".pvd")
    throw InputError("cannot render '" + source + "': expected a run directory, a .pvd series or a .vtu snapshot");
  std::vector<Snapshot> out;
  for (const io::PvdEntry& e : io::readPvdFile(pvd.string()))
    out.push_back({(pvd.parent_path() / e.file).string(), e.time});
  if (out.empty()) throw InputError("series '" + pvd.string() + "' lists no snapshot");
  return out;
}

// The full path of `program` on the PATH, or "".
std::string findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / program;
    if (!dirs.substr(start, end - start).empty() && ::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    start = end + 1;
  }
  return "";
}

// Runs a program with arguments (no shell); its exit status, or -1.
int runProgram(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0].c_str(), nullptr, nullptr, args.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

SeriesPictures writeSeriesPictures(const std::string& source, const std::string& out_dir,
                                   const SeriesPictureOptions& options) {
  if (options.every < 1) throw InputError("render: every must be >= 1, got " + std::to_string(options.every));
  const std::vector<Snapshot> all = snapshotsOf(source);
  std::vector<Snapshot> chosen;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (i % static_cast<std::size_t>(options.every) == 0 || i + 1 == all.size()) chosen.push_back(all[i]);

  // First pass: one view and one colour range for every frame.
  ViewExtent extent(options.picture.view);
  std::optional<ColourRange> range = options.picture.range;
  const bool coloured = !options.picture.property.empty();
  for (const Snapshot& s : chosen) {
    const Tissue t = io::readTissueVtu(s.path);
    extent.add(t);
    if (coloured && !options.picture.range) {
      std::vector<double> values;
      try {
        values = cellValues(t, options.picture.property);
      } catch (const InputError& e) {
        throw InputError(s.path + ": " + e.what());
      }
      if (const auto r = valueRange(values))
        range = range ? ColourRange{std::min(range->low, r->low), std::max(range->high, r->high)} : *r;
    }
  }
  SeriesPictures out;
  PictureOptions picture = options.picture;
  if (coloured) picture.range = range.value_or(ColourRange{});
  out.range = picture.range.value_or(ColourRange{});
  const View view = extent.fit(picture);

  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) throw InputError("cannot create the output directory '" + out_dir + "': " + ec.message());
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const Tissue t = io::readTissueVtu(chosen[i].path);
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06zu.png", i);
    picture.title = options.picture.title.empty() ? "t = " + formatNumber(t.time()) : options.picture.title;
    const std::string path = (fs::path(out_dir) / name).string();
    writePicture(t, view, picture, path);
    out.frames.push_back(path);
  }

  if (!options.movie) return out;
  const std::string ffmpeg = findOnPath("ffmpeg");
  if (ffmpeg.empty()) {
    out.movie_note = "no movie: ffmpeg is not installed (apt-get install ffmpeg)";
    return out;
  }
  const std::string movie = (fs::path(out_dir) / "movie.mp4").string();
  // Even dimensions and yuv420p: what common players accept.
  const int status = runProgram({ffmpeg, "-y", "-loglevel", "error", "-framerate", "8", "-i",
                                 (fs::path(out_dir) / "frame_%06d.png").string(), "-vf",
                                 "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", movie});
  if (status == 0)
    out.movie = movie;
  else
    out.movie_note = "no movie: ffmpeg failed (exit status " + std::to_string(status) + ")";
  return out;
}

}  // namespace tessella::render
