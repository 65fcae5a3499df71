// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Pictures: the size asked for, and cells in the colours of their property
// (read back from the PNG at the pixel of each cell's centroid).
#include <cairo.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "tessella/io/pvd.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/render/colour_map.hpp"
#include "tessella/render/picture.hpp"
#include "tessella/render/series_pictures.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::render;
namespace fs = std::filesystem;

namespace {

struct Png {
  cairo_surface_t* surface = nullptr;
  explicit Png(const std::string& path) : surface(cairo_image_surface_create_from_png(path.c_str())) {}
  ~Png() { cairo_surface_destroy(surface); }
  bool ok() const { return cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS; }
  int width() const { return cairo_image_surface_get_width(surface); }
  int height() const { return cairo_image_surface_get_height(surface); }
  // 8-bit red, green, blue of a pixel (RGB24: one 32-bit word, 0x00RRGGBB).
  std::array<int, 3> rgb(int x, int y) const {
    const unsigned char* row = cairo_image_surface_get_data(surface) + y * cairo_image_surface_get_stride(surface);
    const std::uint32_t w = reinterpret_cast<const std::uint32_t*>(row)[x];
    return {static_cast<int>((w >> 16) & 0xff), static_cast<int>((w >> 8) & 0xff), static_cast<int>(w & 0xff)};
  }
};

bool near(const std::array<int, 3>& pixel, const Rgb& c) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(pixel[k] - std::lround(255 * c[k])) > 2) return false;
  return true;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("tessella_render_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("a picture has the size asked for and colours the left half and the right half with the map's ends",
          "[render]") {
  Tissue t = rectangularGrid(4, 2, 1.0, 1.0);
  auto& p = t.cellProperties().add<double>("p", 0.0);
  for (CellId c : t.cells()) p[c] = cellCentroid(t, c).x() < 2.0 ? 0.0 : 1.0;
  PictureOptions o;
  o.property = "p";
  o.width = 400, o.height = 300;
  const fs::path png = scratch("halves") / "p.png";
  const View view = fitView({&t}, o);
  writePicture(t, view, o, png.string());

  const Png image(png.string());
  REQUIRE(image.ok());
  CHECK(image.width() == 400);
  CHECK(image.height() == 300);
  for (CellId c : t.cells()) {
    const auto [x, y] = view.pixel(cellCentroid(t, c));
    INFO("cell " << c.index() << " at pixel " << x << ", " << y);
    CHECK(near(image.rgb(static_cast<int>(x), static_cast<int>(y)), viridis(p[c])));
  }
  // The colour bar's top is the high end, its bottom the low end; the
  // background is white.
  CHECK(near(image.rgb(2, 2), {1, 1, 1}));
}

TEST_CASE("an integer property and the built-in size colour a picture; a missing property is named", "[render]") {
  Tissue t = rectangularGrid(3, 1, 1.0, 1.0);
  auto& n = t.cellProperties().add<std::int32_t>("n", 0);
  n[CellId(0)] = 5, n[CellId(1)] = 7, n[CellId(2)] = 9;
  CHECK(cellValues(t, "n") == std::vector<double>{5, 7, 9});
  CHECK(cellValues(t, "size") == std::vector<double>{1, 1, 1});
  CHECK(valueRange({5, 7, std::nan(""), 9})->low == 5);
  CHECK(valueRange({5, 7, std::nan(""), 9})->high == 9);
  CHECK_THROWS_WITH(cellValues(t, "auxin"), Catch::Contains("no cell property 'auxin'") && Catch::Contains("size, lineage_id") && Catch::Contains(", n)"));
  t.cellProperties().add<Vec3>("direction", Vec3::UnitX());
  CHECK_THROWS_WITH(cellValues(t, "direction"), Catch::Contains("'direction' is not a number per cell"));
  PictureOptions o;
  o.property = "n";
  CHECK_THROWS_WITH(writePicture(t, fitView({&t}, o), o, "/nonexistent-dir/x.png"),
                    Catch::Contains("cannot write picture '/nonexistent-dir/x.png'"));
  o.view = Vec3::Zero();
  CHECK_THROWS_AS(fitView({&t}, o), InputError);
}

TEST_CASE("a 3D tissue is drawn by its outer walls, each in its cell's colour", "[render]") {
  Tissue t = boxGrid(2, 2, 2, 1.0, 1.0, 1.0);
  auto& p = t.cellProperties().add<double>("p", 0.0);
  for (CellId c : t.cells()) p[c] = cellCentroid(t, c).z() > 1.0 ? 1.0 : 0.0;
  PictureOptions o;
  o.property = "p";
  o.width = o.height = 200;
  o.view = Vec3(1, 0, 0);  // from +x: the x = 2 face, z up on the screen
  const fs::path png = scratch("box") / "box.png";
  const View view = fitView({&t}, o);
  writePicture(t, view, o, png.string());
  const Png image(png.string());
  REQUIRE(image.ok());
  const auto top = view.pixel(Vec3(2.0, 1.5, 1.5)), bottom = view.pixel(Vec3(2.0, 0.5, 0.5));
  CHECK(near(image.rgb(static_cast<int>(top[0]), static_cast<int>(top[1])), viridis(1)));
  CHECK(near(image.rgb(static_cast<int>(bottom[0]), static_cast<int>(bottom[1])), viridis(0)));
}

TEST_CASE("the frames of a series share one colour range and one view", "[render]") {
  const fs::path dir = scratch("series");
  std::vector<io::PvdEntry> entries;
  for (int k = 0; k < 3; ++k) {
    Tissue t = rectangularGrid(2, 1, 1.0 + k, 1.0);
    t.setTime(0.5 * k);
    auto& p = t.cellProperties().add<double>("p", 0.0);
    p[CellId(0)] = k, p[CellId(1)] = k + 1;  // 0..1, 1..2, 2..3: the series spans 0..3
    const std::string file = "tissue_00000" + std::to_string(k) + ".vtu";
    io::writeTissueVtu(t, (dir / file).string());
    entries.push_back({0.5 * k, file});
  }
  io::writePvdFile((dir / "tissue.pvd").string(), entries);

  SeriesPictureOptions o;
  o.picture.property = "p";
  o.picture.width = 300, o.picture.height = 200;
  o.movie = false;
  const SeriesPictures made = writeSeriesPictures(dir.string(), (dir / "frames").string(), o);
  REQUIRE(made.frames.size() == 3);
  CHECK(made.range.low == 0.0);
  CHECK(made.range.high == 3.0);
  // The view frames the largest tissue: the last frame (3 x 1) fills the
  // width, so the first frame's right cell (value 1 of 0..3) sits left of
  // the middle, coloured a third of the way along the map.
  PictureOptions shared = o.picture;
  Tissue last = rectangularGrid(2, 1, 3.0, 1.0), first = rectangularGrid(2, 1, 1.0, 1.0);
  const View view = fitView({&first, &last}, shared);
  const Png frame0(made.frames[0]), frame2(made.frames[2]);
  REQUIRE(frame0.ok());
  const auto right0 = view.pixel(Vec3(1.5, 0.5, 0)), right2 = view.pixel(Vec3(4.5, 0.5, 0));
  CHECK(near(frame0.rgb(static_cast<int>(right0[0]), static_cast<int>(right0[1])), viridis(1.0 / 3.0)));
  CHECK(near(frame2.rgb(static_cast<int>(right2[0]), static_cast<int>(right2[1])), viridis(1.0)));

  o.every = 2;
  CHECK(writeSeriesPictures(dir.string(), (dir / "every2").string(), o).frames.size() == 2);  // 0 and the last
  CHECK_THROWS_WITH(writeSeriesPictures((dir / "missing").string(), (dir / "x").string(), o),
                    Catch::Contains("no such file or directory"));
  o.picture.property = "q";
  CHECK_THROWS_WITH(writeSeriesPictures(dir.string(), (dir / "x").string(), o),
                    Catch::Contains("tissue_000000.vtu") && Catch::Contains("no cell property 'q'"));
}
