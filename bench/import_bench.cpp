// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// import_bench: the cost of importing a file next to the cost of merely
// parsing it (the ratio's target: import within 2x of parsing), for
//  - a synthetic MorphoGraphX-style mesh: a square grid of cells, each a fan
//    of 4k triangles around its centre (tests/io/mgx_fixture.hpp), written as
//    binary little-endian and as ASCII PLY;
//  - a 3D cell-complex PLY: a Tessella 3D Voronoi tissue written with
//    io::writeCellComplexPly (binary and ASCII);
// and the time to mesh the imported real meristem (tests/data/mgx_meristem_cropped).
//
//   import_bench [CELLS] [K] [CELLS3D]   defaults: 100000 cells, k = 3 (12 triangles per cell), 10000 3D cells

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "../tests/io/mgx_fixture.hpp"
#include "bench_args.hpp"
#include "bench_figure.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/io/cell_complex_ply.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/ply.hpp"
#include "tessella/mesh/mesh_tissue.hpp"

using namespace tessella;
using Clock = std::chrono::steady_clock;

namespace {
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

template <typename F>
double bestOf(int runs, F&& f) {
  double best = 1e300;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = Clock::now();
    f();
    best = std::min(best, secondsSince(t0));
  }
  return best;
}

// One table row: the file's size, the best of three parses (io::PlyFile::read)
// and imports (parse included), their ratio, and its FIGURE line.
void parseAndImportRow(const std::string& path, bool binary, const std::string& figure) {
  const double mb = double(std::filesystem::file_size(path)) / 1e6;
  const int runs = 3;
  const double parse = bestOf(runs, [&] { io::PlyFile::read(path); });
  std::size_t imported = 0;
  const double import = bestOf(runs, [&] { imported = io::importTissue(path).tissue.numCells(); });
  std::printf("%-22s %10.1f %10.3f %10.3f %8.2f   (%zu cells)\n", binary ? "binary_little_endian" : "ascii", mb,
              parse, import, import / parse, imported);
  bench::printFigure(figure + (binary ? "binary" : "ascii") + "." + std::to_string(imported) + "cells", import, "s",
                     parse, "ply_parse", 2.0);
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage =
      "import_bench [CELLS (default 100000)] [K wall segments per side (default 3)] [CELLS3D (default 10000)]";
  if (bench::helpRequested(argc, argv, usage)) return 0;
  const std::size_t cells = bench::countArgument(argc, argv, 1, "CELLS", 100000, 1, 10000000, usage);
  const std::size_t k = bench::countArgument(argc, argv, 2, "K", 3, 1, 100, usage);
  const std::size_t cells3d = bench::countArgument(argc, argv, 3, "CELLS3D", 10000, 4, 1000000, usage);
  const int nx = static_cast<int>(std::ceil(std::sqrt(double(cells))));
  const int ny = static_cast<int>((cells + nx - 1) / nx);
  const auto m = io::testing::MgxFixture::grid(nx, ny, static_cast<int>(k));
  const auto dir = std::filesystem::temp_directory_path() / "tessella_import_bench";
  std::filesystem::create_directories(dir);
  std::printf("synthetic MorphoGraphX mesh: %d x %d = %d cells, %zu vertices, %zu triangles\n", nx, ny, nx * ny,
              m.positions.size(), m.faces.size());
  std::printf("%-22s %10s %10s %10s %8s\n", "file", "MB", "parse s", "import s", "ratio");
  for (auto format : {io::testing::MgxFixture::Format::BinaryLittleEndian, io::testing::MgxFixture::Format::Ascii}) {
    const bool binary = format != io::testing::MgxFixture::Format::Ascii;
    const std::string path = (dir / (binary ? "mesh_binary.ply" : "mesh_ascii.ply")).string();
    m.write(path, format);
    parseAndImportRow(path, binary, "import.mgx_ply.");
  }

  // A 3D cell complex: a Voronoi tissue in a box, written as OpenAlea writes one.
  const double side = std::cbrt(double(cells3d));
  const Box box{Vec3(0, 0, 0), Vec3(side, side, side)};
  const auto t0 = Clock::now();
  const Tissue voronoi = voronoiTissue(randomSeeds(box, cells3d, 7), box);
  std::printf("\n3D Voronoi tissue: %zu cells, %zu walls, %zu vertices (generated in %.2f s)\n", voronoi.numCells(),
              voronoi.numFaces(), voronoi.numVertices(), secondsSince(t0));
  std::printf("%-22s %10s %10s %10s %8s\n", "file", "MB", "parse s", "import s", "ratio");
  for (bool binary : {true, false}) {
    const std::string path = (dir / (binary ? "complex_binary.ply" : "complex_ascii.ply")).string();
    io::writeCellComplexPly(voronoi, path, io::CellComplexPlyOptions{binary});
    parseAndImportRow(path, binary, "import.cell_complex_ply.");
  }
  std::filesystem::remove_all(dir);

  // Meshing the real meristem, as imported.
  const std::string meristem =
      std::string(TESSELLA_SOURCE_DIR) + "/tests/data/mgx_meristem_cropped/mesh_meristem_cropped_T0.ply";
  if (!std::filesystem::exists(meristem)) {
    std::printf("\nreal meristem: %s is absent, not meshed\n", meristem.c_str());
    return 0;
  }
  Tissue real(2, Embedding::Surface);
  const double import_real = bestOf(3, [&] { real = io::importTissue(meristem).tissue; });
  std::size_t triangles = 0;
  const double mesh_real =
      bestOf(3, [&] { triangles = static_cast<std::size_t>(mesh::meshTissue(real).numElements()); });
  std::printf("\nreal meristem T0 (%zu cells): import %.4f s, mesh %.4f s (%zu triangles)\n", real.numCells(),
              import_real, mesh_real, triangles);
  return 0;
}
