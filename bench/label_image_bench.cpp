// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// label_image_bench: importing a label image (io::importTissue, format
// label_image: read + conversion) next to merely reading it
// (io::readLabelImage), for
//  - a 2D 4096 x 4096 image of about 10^5 cells (issue #15's target: import
//    within 3x the read time),
//  - a 3D 512^3 image of about 10^4 cells (target: import under 30 s on the
//    project's 2-core machine),
// each a discrete Voronoi diagram of jittered-grid seeds (every pixel the
// nearest of the seeds of its own and the neighbouring grid cells) written
// as an uncompressed MetaImage of 32-bit labels. Peak memory (max RSS) is
// printed after each step; it only grows, so a step's own use is the rise.
//
//   label_image_bench [--quick | --2d | --3d]   --quick: 1024^2 (about 6000 cells) and 128^3 (about 1000 cells);
//                                               --2d, --3d: the full size of one dimension only

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "bench_figure.hpp"
#include "process_usage.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/label_image.hpp"
#include "tessella/tissue/builders.hpp"

using namespace tessella;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// A discrete Voronoi label image of n^dim pixels, g^dim jittered-grid seeds
// (each within the middle half of its grid cell), labels 2.. (0 and 1 are
// the default background), written as MetaImage with 32-bit labels.
std::size_t writeVoronoiImage(const std::string& path, int dim, std::int64_t n, std::int64_t g) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> jitter(0.25, 0.75);
  const std::int64_t gz = dim == 3 ? g : 1;
  const double cell = static_cast<double>(n) / static_cast<double>(g);
  std::vector<std::array<double, 3>> seeds(static_cast<std::size_t>(g * g * gz));
  for (auto& s : seeds) s = {jitter(rng), jitter(rng), dim == 3 ? jitter(rng) : 0.5};
  auto seedAt = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    const auto& s = seeds[static_cast<std::size_t>(i + g * (j + g * k))];
    return std::array<double, 3>{(i + s[0]) * cell, (j + s[1]) * cell, (k + s[2]) * cell};
  };
  const std::int64_t nz = dim == 3 ? n : 1;
  std::vector<std::uint32_t> labels(static_cast<std::size_t>(n * n * nz));
  for (std::int64_t z = 0; z < nz; ++z)
    for (std::int64_t y = 0; y < n; ++y)
      for (std::int64_t x = 0; x < n; ++x) {
        const double p[3] = {x + 0.5, y + 0.5, dim == 3 ? z + 0.5 : 0.5 * cell};
        const auto ci = static_cast<std::int64_t>(p[0] / cell), cj = static_cast<std::int64_t>(p[1] / cell),
                   ck = dim == 3 ? static_cast<std::int64_t>(p[2] / cell) : 0;
        // The nearest seed: those of the grid cells within r of p's, r = 1 and, when a seed of a cell
        // farther away could be nearer (each seed lies at least cell/4 inside its grid cell), r = 2.
        double best = 1e300;
        std::int64_t label = 0;
        for (std::int64_t r = 1; r <= 2; ++r) {
          for (std::int64_t k = std::max<std::int64_t>(0, ck - r); k <= std::min(gz - 1, ck + r); ++k)
            for (std::int64_t j = std::max<std::int64_t>(0, cj - r); j <= std::min(g - 1, cj + r); ++j)
              for (std::int64_t i = std::max<std::int64_t>(0, ci - r); i <= std::min(g - 1, ci + r); ++i) {
                const auto s = seedAt(i, j, k);
                const double d = (s[0] - p[0]) * (s[0] - p[0]) + (s[1] - p[1]) * (s[1] - p[1]) +
                                 (s[2] - p[2]) * (s[2] - p[2]);
                const std::int64_t id = i + g * (j + g * k) + 2;
                if (d < best || (d == best && id < label)) best = d, label = id;
              }
          double reach = 1e300;  // how far p is from the grid cells beyond r, plus the cell/4 margin
          const std::int64_t c[3] = {ci, cj, ck};
          for (int a = 0; a < dim; ++a) {
            reach = std::min(reach, p[a] - static_cast<double>(c[a] - r) * cell);
            reach = std::min(reach, static_cast<double>(c[a] + r + 1) * cell - p[a]);
          }
          reach += 0.25 * cell;
          if (best <= reach * reach) break;
        }
        labels[static_cast<std::size_t>(x + n * (y + n * z))] = static_cast<std::uint32_t>(label);
      }
  std::ofstream out(path, std::ios::binary);
  out << "ObjectType = Image\nNDims = " << dim << "\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
      << "DimSize = " << n << " " << n << (dim == 3 ? " " + std::to_string(n) : std::string()) << "\n"
      << "ElementSpacing = 1 1" << (dim == 3 ? " 1" : "") << "\nElementType = MET_UINT\nElementDataFile = LOCAL\n";
  out.write(reinterpret_cast<const char*>(labels.data()),
            static_cast<std::streamsize>(labels.size() * sizeof(std::uint32_t)));
  return seeds.size();
}

// The flat polygon lists of a planar tissue's cells, to time rebuilding it (the floor of a 2D import).
struct Polygons {
  std::vector<Vec3> positions;
  std::vector<Index> offsets{0}, loops;
};
Polygons polygonsOf(const Tissue& t) {
  Polygons p;
  for (VertexId v : t.vertices()) p.positions.push_back(t.position(v));
  for (CellId c : t.cells()) {
    for (VertexId v : t.topology().faceVertices(t.cellFace(c))) p.loops.push_back(v.index());
    p.offsets.push_back(static_cast<Index>(p.loops.size()));
  }
  return p;
}

void row(const std::string& path, int dim, std::int64_t n, std::size_t seeds, double simplify, int runs,
         double target) {
  io::ImportOptions o;
  o.simplify = simplify;
  o.image.keep_pieces = true;  // a pixel nearer a seed two grid cells away may leave a speck of another label
  std::size_t cells = 0, vertices = 0;
  double read = 1e300, import = 1e300, convert = 1e300, build = 1e300, import_cpu = 1e300, read_cpu = 1e300;
  double rss_read = 0;
  // Read and import in turns, so that both see the same machine load.
  for (int r = 0; r < runs; ++r) {
    {
      const auto t0 = Clock::now();
      const double c0 = bench::processCpuSeconds();
      const io::LabelImage img = io::readLabelImage(path);
      read = std::min(read, secondsSince(t0));
      read_cpu = std::min(read_cpu, bench::processCpuSeconds() - c0);
      rss_read = std::max(rss_read, bench::maxRssMb());
      if (r == 0 && dim == 2) {  // the conversion alone (tissueFromLabelImage), from the image in memory
        const auto t1 = Clock::now();
        const io::ImportResult result = io::tissueFromLabelImage(img, o);
        convert = std::min(convert, secondsSince(t1));
      }
    }
    const auto t0 = Clock::now();
    const double c0 = bench::processCpuSeconds();
    const io::ImportResult result = io::importTissue(path, o);
    import = std::min(import, secondsSince(t0));
    import_cpu = std::min(import_cpu, bench::processCpuSeconds() - c0);
    cells = result.tissue.numCells(), vertices = result.tissue.numVertices();
    if (dim == 2) {  // the floor: building the same tissue from its polygons
      const Polygons p = polygonsOf(result.tissue);
      const auto t1 = Clock::now();
      const Tissue t = buildPolygonTissue(p.positions, p.offsets, p.loops);
      build = std::min(build, secondsSince(t1));
    }
  }
  const double rss_import = bench::maxRssMb();
  const std::string size = dim == 3 ? std::to_string(n) + "^3" : std::to_string(n) + "^2";
  std::printf("%-3dD %-8s %8zu %8zu %9zu %8.3f %9.3f %8.3f %8.3f %8.3f %8.3f %7.2f %9.2f %10.0f %9.0f %10.0f\n", dim,
              size.c_str(), seeds, cells, vertices, read, import, read_cpu, import_cpu, dim == 2 ? convert : 0.0,
              dim == 2 ? build : 0.0, import / read, import_cpu / read_cpu, static_cast<double>(cells) / import,
              rss_read, rss_import);
  const std::string name = "import.label_image_" + std::to_string(dim) + "d." + size + "." + std::to_string(cells) +
                           "cells.simplify" + (simplify > 0 ? "1" : "0");
  if (dim == 2) {
    bench::printFigure(name, import, "s", read, "image_read", target);
  } else {
    bench::printFigure(name, import, "s", target);
    bench::printFigure(name + ".vs_read", import, "s", read, "image_read", bench::kNoTarget);
  }
  bench::printFigure(name + ".cells_per_s", static_cast<double>(cells) / import, "cells/s", bench::kNoTarget,
                     bench::Better::Higher);
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage =
      "label_image_bench [--quick | --2d | --3d]   (default: 4096^2 with ~10^5 cells, 512^3 with ~10^4 cells)";
  const std::string flag = bench::flagArgument(argc, argv, {"--quick", "--2d", "--3d"}, usage);
  const bool quick = flag == "--quick";
  const auto dir = std::filesystem::temp_directory_path() / "tessella_label_image_bench";
  std::filesystem::create_directories(dir);
  const std::int64_t n2 = quick ? 1024 : 4096, g2 = quick ? 78 : 316;  // 316^2 = 99856 seeds
  const std::int64_t n3 = quick ? 128 : 512, g3 = quick ? 10 : 22;     // 22^3 = 10648 seeds
  std::printf("%-4s %-8s %8s %8s %9s %8s %9s %8s %8s %8s %8s %7s %9s %10s %9s %10s\n", "dim", "size", "seeds",
              "cells", "vertices", "read s", "import s", "read CPU", "CPU s", "convert", "build", "ratio",
              "CPU ratio", "cells/s", "RSS read", "RSS import");
  if (flag != "--3d") {
    const std::string path = (dir / "cells_2d.mha").string();
    const std::size_t seeds = writeVoronoiImage(path, 2, n2, g2);
    // The 3x target is the for 4096^2; the quick size has none: its read (a few ms) is decided by
    // whether malloc hands back memory an earlier run freed (arrays under glibc's 32 MB mmap threshold are
    // reused without page faults: 1 ms warm against 15 ms cold), so its ratio is noise.
    const double target = quick ? bench::kNoTarget : 3.0;
    for (const double simplify : {0.0, 1.0}) row(path, 2, n2, seeds, simplify, 3, target);
    std::filesystem::remove(path);
  }
  if (flag != "--2d") {
    const std::string path = (dir / "cells_3d.mha").string();
    const std::size_t seeds = writeVoronoiImage(path, 3, n3, g3);
    // The 30 s target is the for 512^3; the quick size has none.
    const double target = quick ? bench::kNoTarget : 30.0;
    for (const double simplify : {0.0, 1.0}) row(path, 3, n3, seeds, simplify, quick ? 3 : 1, target);
    std::filesystem::remove(path);
  }
  std::printf("(RSS in MB, the process's peak so far; import includes reading the file; read CPU, CPU s: the read's "
              "and the import's CPU time, all threads (best of the runs), CPU ratio their ratio; ratio: of the wall "
              "times (the FIGURE's); the file is read from the page cache (written just before, read in every run); "
              "2D only: convert, tissueFromLabelImage alone, the image in memory; build, "
              "buildPolygonTissue of the imported cells' polygons alone, the floor of a 2D import)\n");
  return 0;
}
