// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// io_bench: how fast tissue snapshots are written and read.
//
//   io_bench [N] [REPEATS] [DIR] [--codec none|lz4|zlib]
//
// (default 1000 -> an N x N grid = 10^6 cells, 3 repeats, /tmp, every codec;
// --codec measures one, e.g. to profile its read path.)
//
// For each compression it prints the best of REPEATS write times (wall and
// process CPU: CPU time includes the OpenMP geometry threads), the file
// size, the throughput in MB/s of uncompressed array data (points,
// connectivity, offsets, types and cell data, i.e. what VTK has to push
// through the compressor) and of file bytes, then one read-back time.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "bench_figure.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/generators/grids.hpp"

namespace {

double seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }

struct Timing {
  double wall = 1e300;
  double cpu = 1e300;  // process CPU time: on a shared machine wall time also counts waiting
};

template <typename F>
Timing bestOf(int repeats, F&& f) {
  Timing best;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    f();
    best.cpu = std::min(best.cpu, static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
    best.wall = std::min(best.wall, seconds(std::chrono::steady_clock::now() - start));
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tessella;
  const char* usage = "io_bench [N [REPEATS [DIR]]] [--codec none|lz4|zlib]   (an N x N grid; defaults 1000 3 /tmp)";
  if (bench::helpRequested(argc, argv, usage)) return 0;
  // --codec C, anywhere: taken out before the positional arguments are read.
  std::vector<io::Compression> codecs = {io::Compression::None, io::Compression::LZ4, io::Compression::ZLib};
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::string(argv[i]) != "--codec") {
      args.push_back(argv[i]);
      continue;
    }
    const std::string name = i + 1 < argc ? argv[++i] : "";
    const auto it = std::find_if(codecs.begin(), codecs.end(),
                                 [&](io::Compression c) { return name == io::compressionName(c); });
    if (it == codecs.end()) {
      std::fprintf(stderr, "io_bench: --codec must be none, lz4 or zlib, got '%s'\nusage: %s\n", name.c_str(), usage);
      return 2;
    }
    codecs = {*it};
  }
  argc = static_cast<int>(args.size());
  argv = args.data();
  const std::size_t n = bench::countArgument(argc, argv, 1, "N", 1000, 1, 20000, usage);
  const int repeats = static_cast<int>(bench::countArgument(argc, argv, 2, "REPEATS", 3, 1, 1000, usage));
  const std::filesystem::path dir = argc > 3 ? argv[3] : std::filesystem::temp_directory_path();
  if (std::error_code ec; !std::filesystem::is_directory(dir, ec)) {
    std::fprintf(stderr, "io_bench: '%s' is not a directory\nusage: %s\n", dir.c_str(), usage);
    return 2;
  }
  try {
    const auto build_start = std::chrono::steady_clock::now();
    Tissue t = rectangularGrid(n, n);
    auto& auxin = t.cellProperties().add<double>("auxin", 0.0);
    for (CellId c : t.cells()) auxin[c] = 1.0 + 1e-3 * (c.index() % 1000);
    std::printf("tissue: %zu cells, %zu vertices (built in %.2f s)\n", t.numCells(), t.numVertices(),
                seconds(std::chrono::steady_clock::now() - build_start));

    // Array bytes VTK serialises: xyz points, 4 connectivity ids + 1 offset +
    // 1 type per cell, and 5 cell arrays of 8 bytes (lineage_id, parent_id,
    // birth_time, auxin, area).
    const double raw_mb = (24.0 * t.numVertices() + t.numCells() * (8.0 * 4 + 8 + 1 + 5 * 8)) / 1e6;
    std::printf("uncompressed array data: %.1f MB\n\n", raw_mb);
    std::printf("%-6s %10s %10s %10s %12s %12s %10s\n", "codec", "write s", "write cpu", "size MB", "array MB/s",
                "file MB/s", "read s");
    struct Figure {
      io::Compression codec;
      double read, write;
    };
    std::vector<Figure> figures;  // printed after the table
    for (io::Compression c : codecs) {
      io::VtuOptions options;
      options.compression = c;
      const std::string path = (dir / ("io_bench_" + std::string(io::compressionName(c)) + ".vtu")).string();
      const Timing write = bestOf(repeats, [&] { io::writeTissueVtu(t, path, options); });
      const double size_mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
      const Timing read = bestOf(1, [&] {
        const Tissue r = io::readTissueVtu(path);
        if (r.numCells() != t.numCells()) throw std::runtime_error("read-back cell count differs");
      });
      std::printf("%-6s %10.3f %10.3f %10.1f %12.0f %12.0f %10.2f\n", io::compressionName(c), write.wall, write.cpu,
                  size_mb, raw_mb / write.wall, size_mb / write.wall, read.wall);
      figures.push_back({c, read.wall, write.wall});
      std::filesystem::remove(path);
    }
    // issue #19: reading an LZ4 snapshot within 3x of writing it
    for (const Figure& f : figures)
      bench::printFigure(std::string("io.read.") + io::compressionName(f.codec) + "." + std::to_string(t.numCells()) +
                             "cells",
                         f.read, "s", f.write, "write", f.codec == io::Compression::LZ4 ? 3.0 : bench::kNoTarget);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "io_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
