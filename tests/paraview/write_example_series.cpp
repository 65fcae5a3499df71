// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Writes a small growing, dividing tissue as a ParaView series, and a JSON
// file of what each step contains, for the ParaView test to compare with what
// ParaView reads.
//
//   write_example_series OUTPUT_DIR EXPECTED_JSON

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "tessella/io/series.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: write_example_series OUTPUT_DIR EXPECTED_JSON\n";
    return 2;
  }
  using namespace tessella;
  try {
    Tissue t = rectangularGrid(8, 5);
    auto& auxin = t.cellProperties().add<double>("auxin", 0.0, DivisionPolicy::SplitByMeasure);
    auto& type = t.cellProperties().add<std::int32_t>("cell_type", 0);
    for (CellId c : t.cells()) {
      const Vec3 centre = cellCentroid(t, c);
      auxin[c] = std::exp(-0.1 * ((centre.x() - 4) * (centre.x() - 4) + (centre.y() - 2.5) * (centre.y() - 2.5)));
      type[c] = centre.y() > 4 ? 1 : 0;
    }
    io::SeriesWriter series(argv[1], "tissue");
    std::ofstream expected(argv[2]);
    expected << "{\n  \"steps\": [\n";
    const int steps = 3;
    for (int step = 0; step < steps; ++step) {
      t.setTime(0.5 * step);
      series.write(t, t.time());
      expected << "    {\"time\": " << t.time() << ", \"cells\": " << t.numCells()
               << ", \"points\": " << t.numVertices() << "}" << (step + 1 < steps ? "," : "") << "\n";
      // Grow along y, then divide cells 0 and 7 (the bottom corners) across their main axis.
      for (Vec3& p : t.mutablePositions()) p.y() *= 1.2;
      for (Index i : {0u, 7u}) {
        const CellId c(i);
        t.splitCell(c, Plane{cellCentroid(t, c), cellPrincipalAxes(t, c).axes.col(0)});
      }
    }
    expected << "  ],\n  \"cell_arrays\": [\"area\", \"auxin\", \"birth_time\", \"cell_type\", \"lineage_id\", "
                "\"parent_id\"],\n  \"pvd\": \""
             << series.pvdPath() << "\"\n}\n";
    if (!expected) throw std::runtime_error(std::string("cannot write ") + argv[2]);
  } catch (const std::exception& e) {
    std::cerr << "write_example_series: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
