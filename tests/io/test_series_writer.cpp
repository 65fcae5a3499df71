// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Time series: the .pvd is a valid collection after every step, lists every
// step with its time, and every listed file exists and reads back.

#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>

#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include "io_test_support.hpp"
#include "tessella/io/pvd.hpp"
#include "tessella/io/series.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using Catch::Contains;

TEST_CASE("three steps give a .pvd listing three files with their times", "[io][series]") {
  TempDir dir;
  const std::string out = dir.file("run");  // created by the writer
  SeriesWriter series(out, "tissue");
  REQUIRE(series.pvdPath() == (std::filesystem::path(out) / "tissue.pvd").string());

  Tissue t = rectangularGrid(3, 2);
  const std::vector<double> times = {0.0, 0.1, 1.0 / 3.0};
  for (std::size_t step = 0; step < times.size(); ++step) {
    t.setTime(times[step]);
    const std::string written = series.write(t, times[step]);
    REQUIRE(written == (std::filesystem::path(out) / ("tissue_00000" + std::to_string(step) + ".vtu")).string());
    // After every step the collection is complete and lists exactly the steps so far.
    const auto entries = readPvdFile(series.pvdPath());
    REQUIRE(entries.size() == step + 1);
    REQUIRE(series.steps() == step + 1);
    // Divide a cell so that every step has a different cell count.
    t.splitCell(CellId(0), Plane{cellCentroid(t, CellId(0)), Vec3(1, 0.2, 0)});
  }

  const auto entries = readPvdFile(series.pvdPath());
  REQUIRE(entries.size() == 3);
  for (std::size_t step = 0; step < 3; ++step) {
    REQUIRE(entries[step].time == times[step]);  // 17 digits: exact
    REQUIRE(entries[step].file == "tissue_00000" + std::to_string(step) + ".vtu");
    const std::string file = (std::filesystem::path(out) / entries[step].file).string();
    REQUIRE(std::filesystem::exists(file));
    const Tissue r = readTissueVtu(file);
    REQUIRE(r.numCells() == 6 + step);
    REQUIRE(r.time() == times[step]);
  }
}

TEST_CASE("the .pvd is a VTK Collection that VTK's own XML parser accepts", "[io][series]") {
  TempDir dir;
  SeriesWriter series(dir.path().string(), "a&b");  // a name that needs XML escaping
  const Tissue t = rectangularGrid(1, 1);
  series.write(t, 0.5);
  series.write(t, 1.5);

  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(series.pvdPath().c_str());
  REQUIRE(parser->Parse() == 1);
  vtkXMLDataElement* root = parser->GetRootElement();
  REQUIRE(std::string(root->GetName()) == "VTKFile");
  REQUIRE(std::string(root->GetAttribute("type")) == "Collection");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  REQUIRE(collection != nullptr);
  REQUIRE(collection->GetNumberOfNestedElements() == 2);
  vtkXMLDataElement* second = collection->GetNestedElement(1);
  REQUIRE(std::string(second->GetAttribute("file")) == "a&b_000001.vtu");
  double timestep = 0;
  REQUIRE(second->GetScalarAttribute("timestep", timestep) == 1);
  REQUIRE(timestep == 1.5);
  REQUIRE(std::filesystem::exists(dir.file("a&b_000001.vtu")));
}

TEST_CASE("series errors are clear and keep what was written", "[io][series][errors]") {
  TempDir dir;
  SeriesWriter series(dir.path().string(), "s");
  const Tissue t = rectangularGrid(2, 1);
  series.write(t, 1.0);
  REQUIRE_THROWS_WITH(series.write(t, 1.0), Contains("1 is not after the previous step's time 1"));
  REQUIRE_THROWS_WITH(series.write(t, std::nan("")), Contains("not finite"));
  REQUIRE(series.steps() == 1);
  REQUIRE(readPvdFile(series.pvdPath()).size() == 1);
  series.write(t, 2.0);
  REQUIRE(readPvdFile(series.pvdPath()).size() == 2);

  REQUIRE_THROWS_WITH(SeriesWriter(dir.path().string(), "a/b"), Contains("'a/b'"));
  REQUIRE_THROWS_WITH(SeriesWriter(dir.path().string(), ""), Contains("must not be empty"));
  // A regular file where the directory should be.
  std::ofstream(dir.file("plain")) << "x";
  REQUIRE_THROWS_WITH(SeriesWriter(dir.file("plain/sub"), "s"), Contains(dir.file("plain/sub")));
}

TEST_CASE("readPvdFile refuses what is not a collection", "[io][series][errors]") {
  TempDir dir;
  REQUIRE_THROWS_WITH(readPvdFile(dir.file("none.pvd")), Contains("no such file"));
  const std::string broken = dir.file("broken.pvd");
  std::ofstream(broken) << "<VTKFile type=\"Collection\"><Collection><DataSet file=\"x.vtu\"/>";
  REQUIRE_THROWS_WITH(readPvdFile(broken), Contains(broken) && Contains("well-formed"));
  const std::string no_time = dir.file("no_time.pvd");
  std::ofstream(no_time) << "<VTKFile type=\"Collection\"><Collection><DataSet file=\"x.vtu\"/></Collection></VTKFile>";
  REQUIRE_THROWS_WITH(readPvdFile(no_time), Contains("'x.vtu'") && Contains("no timestep"));
  const std::string bad_time = dir.file("bad_time.pvd");
  std::ofstream(bad_time) << "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"soon\" file=\"x.vtu\"/>"
                             "</Collection></VTKFile>";
  REQUIRE_THROWS_WITH(readPvdFile(bad_time), Contains("'soon'"));
}
