// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Label images into planar tissues: Tessella's own Voronoi tissue rasterised
// (point in polygon at every pixel centre) and imported back must give the
// same adjacency, areas converging as the pixels shrink and junctions within
// a pixel; through every file format and with a clear error for each bad input.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include <catch2/catch.hpp>
#include <omp.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMetaImageWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkTIFFWriter.h>
#include <vtkUnsignedShortArray.h>
#include <vtkAOSDataArrayTemplate.h>
#include <vtkXMLImageDataWriter.h>

#include "io_test_support.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/label_image.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using Catch::Matchers::Contains;

namespace {

constexpr std::int64_t kLabelOffset = 2;  // cell c gets label c + 2 (0 and 1 are background by default)

// The Voronoi tissue of the test: 200 cells in the unit square, Lloyd-relaxed.
const Tissue& voronoi200() {
  static const Tissue t = [] {
    VoronoiOptions options;
    options.lloyd_iterations = 10;
    return voronoiTissue(randomSeeds(Rectangle{}, 200, 7), Rectangle{}, options);
  }();
  return t;
}

std::vector<Vec3> loopOf(const Tissue& t, CellId c) {
  std::vector<Vec3> loop;
  for (VertexId v : t.topology().faceVertices(t.cellFace(c))) loop.push_back(t.position(v));
  return loop;
}

bool inside(const std::vector<Vec3>& loop, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Vec3 &p = loop[i], &q = loop[j];
    if ((p.y() > y) != (q.y() > y) && x < (q.x() - p.x()) * (y - p.y()) / (q.y() - p.y()) + p.x()) in = !in;
  }
  return in;
}

// n x n pixels over the unit square, pixel (i, j) = [i/n, (i+1)/n] x [j/n, (j+1)/n]:
// the label of the cell holding its centre (0 where none does).
LabelImage rasterise(const Tissue& t, std::int64_t n) {
  LabelImage img;
  img.name = "voronoi rasterised at " + std::to_string(n);
  img.dims = {n, n, 1};
  img.spacing = {1.0 / n, 1.0 / n, 1};
  img.origin = {0.5 / n, 0.5 / n, 0};  // pixel centres
  img.labels.assign(static_cast<std::size_t>(n * n), 0);
  for (CellId c : t.cells()) {
    const auto loop = loopOf(t, c);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const Vec3& p : loop) x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y()), x1 = std::max(x1, p.x()),
                               y1 = std::max(y1, p.y());
    const auto i0 = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(x0 * n - 0.5)));
    const auto i1 = std::min<std::int64_t>(n - 1, static_cast<std::int64_t>(std::ceil(x1 * n)));
    const auto j0 = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(y0 * n - 0.5)));
    const auto j1 = std::min<std::int64_t>(n - 1, static_cast<std::int64_t>(std::ceil(y1 * n)));
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t i = i0; i <= i1; ++i)
        if (inside(loop, (i + 0.5) / n, (j + 0.5) / n))
          img.labels[static_cast<std::size_t>(j * n + i)] = c.index() + kLabelOffset;
  }
  return img;
}

// Neighbour pairs (by label) and the length of the wall(s) they share.
std::map<std::pair<std::int64_t, std::int64_t>, double> neighbourPairs(const Tissue& t, bool use_label) {
  const auto* label = use_label ? &t.cellProperties().get<std::int64_t>("label") : nullptr;
  auto id = [&](CellId c) { return label ? (*label)[c] : static_cast<std::int64_t>(c.index()) + kLabelOffset; };
  std::map<std::pair<std::int64_t, std::int64_t>, double> pairs;
  for (WallId w : t.walls()) {
    const auto cs = t.wallCells(w);
    const auto [a, b] = t.topology().edgeVertices(EdgeId(w.index()));
    if (cs.size() == 2) pairs[std::minmax(id(cs[0]), id(cs[1]))] += (t.position(a) - t.position(b)).norm();
  }
  return pairs;
}

std::set<std::int64_t> boundaryCells(const Tissue& t, bool use_label) {
  const auto* label = use_label ? &t.cellProperties().get<std::int64_t>("label") : nullptr;
  std::set<std::int64_t> out;
  for (WallId w : t.walls())
    if (t.isBoundaryWall(w)) {
      const CellId c = t.wallCells(w)[0];
      out.insert(label ? (*label)[c] : static_cast<std::int64_t>(c.index()) + kLabelOffset);
    }
  return out;
}

// Vertices where three or more walls meet.
std::vector<Vec3> junctions(const Tissue& t) {
  std::vector<Vec3> out;
  for (VertexId v : t.vertices())
    if (t.topology().vertexEdges(v).size() >= 3) out.push_back(t.position(v));
  return out;
}

std::map<std::int64_t, double> areasByLabel(const Tissue& t) {
  const auto& label = t.cellProperties().get<std::int64_t>("label");
  std::map<std::int64_t, double> out;
  for (CellId c : t.cells()) out[label[c]] = cellMeasure(t, c);
  return out;
}

struct Fit {
  double mean_area_error = 0, max_area_error = 0, max_junction_distance = 0;
  std::size_t pairs_differing = 0;
};

// Compares an imported tissue with the original: the neighbour pairs are the
// same but for walls shorter than `resolved` (in the original when the pair
// is missing, in the import when it is new: four cells meeting within a few
// pixels cannot be told apart); boundary cells exactly; areas and junctions measured.
Fit compare(const Tissue& original, const Tissue& imported, double resolved) {
  REQUIRE(validate(imported).ok);
  REQUIRE(imported.numCells() == original.numCells());
  const auto want = neighbourPairs(original, false), got = neighbourPairs(imported, true);
  Fit fit;
  for (const auto& [pair, length] : want)
    if (!got.count(pair)) {
      ++fit.pairs_differing;
      INFO("pair " << pair.first << "-" << pair.second << " lost, its wall is " << length);
      CHECK(length < resolved);
    }
  for (const auto& [pair, length] : got)
    if (!want.count(pair)) {
      ++fit.pairs_differing;
      INFO("pair " << pair.first << "-" << pair.second << " appears, its wall is " << length);
      CHECK(length < resolved);
    }
  CHECK(boundaryCells(imported, true) == boundaryCells(original, false));
  const auto areas = areasByLabel(imported);
  for (CellId c : original.cells()) {
    const double a = cellMeasure(original, c);
    const double err = std::abs(areas.at(c.index() + kLabelOffset) - a) / a;
    fit.mean_area_error += err / static_cast<double>(original.numCells());
    fit.max_area_error = std::max(fit.max_area_error, err);
  }
  const auto want_j = junctions(original), got_j = junctions(imported);
  if (fit.pairs_differing == 0) CHECK(got_j.size() == want_j.size());
  for (const Vec3& p : want_j) {
    double nearest = 1e300;
    for (const Vec3& q : got_j) nearest = std::min(nearest, (p - q).norm());
    fit.max_junction_distance = std::max(fit.max_junction_distance, nearest);
  }
  return fit;
}

void writeVtkImage(const LabelImage& img, const std::string& path, bool as_float = false) {
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(static_cast<int>(img.dims[0]), static_cast<int>(img.dims[1]), static_cast<int>(img.dims[2]));
  data->SetSpacing(img.spacing.data());
  data->SetOrigin(img.origin.data());
  vtkSmartPointer<vtkDataArray> values;
  if (as_float) values = vtkSmartPointer<vtkFloatArray>::New();
  else values = vtkSmartPointer<vtkUnsignedShortArray>::New();
  values->SetName("labels");
  values->SetNumberOfTuples(static_cast<vtkIdType>(img.labels.size()));
  for (std::size_t k = 0; k < img.labels.size(); ++k)
    values->SetTuple1(static_cast<vtkIdType>(k), static_cast<double>(img.labels[k]));
  data->GetPointData()->SetScalars(values);
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".vti") {
    auto w = vtkSmartPointer<vtkXMLImageDataWriter>::New();
    w->SetFileName(path.c_str());
    w->SetInputData(data);
    REQUIRE(w->Write() == 1);
  } else if (ext == ".mha") {
    auto w = vtkSmartPointer<vtkMetaImageWriter>::New();
    w->SetFileName(path.c_str());
    w->SetCompression(false);
    w->SetInputData(data);
    w->Write();
  } else if (ext == ".tif") {
    auto w = vtkSmartPointer<vtkTIFFWriter>::New();
    w->SetFileName(path.c_str());
    w->SetInputData(data);
    w->Write();
  } else {
    FAIL("no writer for " << path);
  }
  REQUIRE(std::filesystem::exists(path));
}

// NRRD, written by hand (VTK has a reader only): a text header and raw
// little-endian 16-bit labels, x fastest.
void writeNrrd(const LabelImage& img, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out.precision(17);
  out << "NRRD0004\ntype: uint16\ndimension: 2\nsizes: " << img.dims[0] << " " << img.dims[1]
      << "\nspacings: " << img.spacing[0] << " " << img.spacing[1] << "\nendian: little\nencoding: raw\n\n";
  for (std::int64_t l : img.labels) {
    const auto v = static_cast<std::uint16_t>(l);
    const char bytes[2] = {static_cast<char>(v & 0xff), static_cast<char>(v >> 8)};
    out.write(bytes, 2);
  }
}

// A small image from rows written top row first (as it would be drawn), one
// character per pixel: '.' = 0, digits and letters = their value.
LabelImage drawn(const std::vector<std::string>& rows) {
  LabelImage img;
  img.name = "drawn";
  const auto h = static_cast<std::int64_t>(rows.size()), w = static_cast<std::int64_t>(rows[0].size());
  img.dims = {w, h, 1};
  img.labels.resize(static_cast<std::size_t>(w * h));
  for (std::int64_t j = 0; j < h; ++j)
    for (std::int64_t i = 0; i < w; ++i) {
      const char ch = rows[static_cast<std::size_t>(h - 1 - j)][static_cast<std::size_t>(i)];
      img.labels[static_cast<std::size_t>(j * w + i)] =
          ch == '.' ? 0 : std::isdigit(static_cast<unsigned char>(ch)) ? ch - '0' : ch - 'a' + 10;
    }
  return img;
}

ImportOptions withImage(LabelImageOptions image, double simplify = 0) {
  ImportOptions o;
  o.simplify = simplify;
  o.image = std::move(image);
  return o;
}

}  // namespace

TEST_CASE("a rasterised 200-cell Voronoi tissue imports back with the same adjacency", "[io][label_image]") {
  const Tissue& original = voronoi200();
  REQUIRE(original.numCells() == 200);
  std::size_t short_walls = 0;
  std::map<double, std::vector<Fit>> fits;  // by simplify
  for (const std::int64_t n : {512, 1024}) {
    const double h = 1.0 / static_cast<double>(n);
    for (EdgeId e : original.edges()) {
      const auto [a, b] = original.topology().edgeVertices(e);
      short_walls += n == 512 && (original.position(a) - original.position(b)).norm() < 3 * h;
    }
    const LabelImage img = rasterise(original, n);
    for (const double simplify : {0.0, 1.0, 2.0}) {
      const ImportResult r = tissueFromLabelImage(img, withImage({}, simplify));
      const Fit fit = compare(original, r.tissue, 3 * h);
      INFO("n " << n << " simplify " << simplify);
      CHECK(fit.max_junction_distance <= 1.5 * h);
      fits[simplify].push_back(fit);
      WARN("n " << n << " simplify " << simplify << ": area error mean " << fit.mean_area_error << " max "
                << fit.max_area_error << ", junctions within " << fit.max_junction_distance / h << " px, "
                << fit.pairs_differing << " pairs differ, " << r.tissue.numVertices() << " vertices");
    }
  }
  WARN(short_walls << " walls shorter than 3 px at 512");
  CHECK(fits[0.0][1].pairs_differing <= fits[0.0][0].pairs_differing);
  // Areas converge. The staircase (simplify 0) has the area of the pixel
  // count, whose error at the boundary pixels partly cancels: its mean
  // relative error falls at least like h. Simplified walls (a tolerance in
  // pixels, so a bias of order h) still converge, at least like h^(1/2).
  for (const auto& [simplify, f] : fits) {
    const double order = std::log2(f[0].mean_area_error / f[1].mean_area_error);
    WARN("simplify " << simplify << ": observed order of the mean area error " << order << ", of the max "
                     << std::log2(f[0].max_area_error / f[1].max_area_error));
    CHECK(order >= (simplify == 0 ? 1.0 : 0.5));
  }
}

TEST_CASE("label images import through TIFF, NRRD, MetaImage and VTK image files", "[io][label_image]") {
  TempDir dir;
  const Tissue& original = voronoi200();
  const std::int64_t n = 512;
  const double h = 1.0 / n;
  const LabelImage img = rasterise(original, n);
  // vtkTIFFWriter stores VTK's top row (the largest j) first, and the reader
  // takes the first stored row as j = 0 (as NumPy and the TIFF convention
  // do; tests/python checks it with a TIFF written by Pillow), so a TIFF
  // written by VTK comes back mirrored in y.
  LabelImage flipped = img;
  for (std::int64_t j = 0; j < n; ++j)
    for (std::int64_t i = 0; i < n; ++i)
      flipped.labels[static_cast<std::size_t>(j * n + i)] = img.labels[static_cast<std::size_t>((n - 1 - j) * n + i)];
  const ImportResult direct_upright = tissueFromLabelImage(img, withImage({}, 1.0));
  const ImportResult direct_flipped = tissueFromLabelImage(flipped, withImage({}, 1.0));
  for (const std::string name : {"cells.tif", "cells.nrrd", "cells.mha", "cells.vti"}) {
    const std::string path = dir.file(name);
    if (name == "cells.nrrd") writeNrrd(img, path);
    else writeVtkImage(img, path);
    INFO(name);
    const bool tiff = name == "cells.tif";
    const LabelImage& want = tiff ? flipped : img;
    const ImportResult& direct = tiff ? direct_flipped : direct_upright;
    ImportOptions o = withImage({}, 1.0);
    // TIFF and NRRD files carry no origin here, TIFF no pixel size either: give it.
    if (tiff) o.image.voxel_size = {h, h};
    const ImportResult r = importTissue(path, o);
    CHECK(r.report.format == "label_image");
    CHECK(r.report.path == path);
    const LabelImage back = readLabelImage(path);
    std::size_t differ = 0;
    for (std::size_t k = 0; k < img.labels.size(); ++k) differ += back.labels[k] != want.labels[k];
    CHECK(differ == 0);
    CHECK(back.dims == img.dims);
    if (!tiff) CHECK(std::abs(back.spacing[0] - h) < 1e-9 * h);
    // The same tissue as from the array, up to the origin the file kept.
    REQUIRE(r.tissue.numCells() == direct.tissue.numCells());
    REQUIRE(r.tissue.numVertices() == direct.tissue.numVertices());
    const Vec3 shift(back.origin[0] - img.origin[0], back.origin[1] - img.origin[1], 0);
    double worst = 0;
    for (VertexId v : r.tissue.vertices())
      worst = std::max(worst, (r.tissue.position(v) - shift - direct.tissue.position(v)).norm());
    CHECK(worst < 1e-9);
    std::vector<std::pair<std::int64_t, std::int64_t>> a, b;
    for (const auto& [pair, length] : neighbourPairs(r.tissue, true)) a.push_back(pair);
    for (const auto& [pair, length] : neighbourPairs(direct.tissue, true)) b.push_back(pair);
    CHECK(a == b);
  }
}

TEST_CASE("label image options: background, dropped labels, small cells, crop, pieces", "[io][label_image]") {
  // Labels 2, 3, 4 side by side, a 2-pixel label 5 inside 3, label 1 (background) on the left.
  const LabelImage img = drawn({
      "1222333444",
      "1222353444",
      "1222353444",
      "1222333444",
  });
  auto labels = [](const ImportResult& r) {
    std::vector<std::int64_t> out;
    const auto& l = r.tissue.cellProperties().get<std::int64_t>("label");
    for (CellId c : r.tissue.cells()) out.push_back(l[c]);
    return out;
  };
  // Label 5 makes a hole in 3.
  CHECK_THROWS_WITH(tissueFromLabelImage(img, {}),
                    Contains("'drawn': label 3") && Contains("has a hole: it surrounds label(s) 5"));
  SECTION("merged into the neighbour sharing the longest wall") {
    LabelImageOptions o;
    o.min_cell_size = 3;
    o.small_cells = "merge";
    const ImportResult r = tissueFromLabelImage(img, withImage(o));
    CHECK(labels(r) == std::vector<std::int64_t>{2, 3, 4});
    REQUIRE(validate(r.tissue).ok);
    const auto areas = areasByLabel(r.tissue);
    CHECK(areas.at(3) == Approx(12.0));  // 10 pixels of 3 and the 2 of 5, unit pixels
    CHECK(areas.at(2) == Approx(12.0));
    bool noted = false;
    for (const auto& note : r.report.notes)
      noted = noted || note.find("label 5 (2 pixels < min_cell_size) merged into label 3") != std::string::npos;
    CHECK(noted);
  }
  SECTION("dropped labels become background; 1 is background by default, 0 can be a cell") {
    LabelImageOptions o;
    o.drop_labels = {5};
    CHECK_THROWS_WITH(tissueFromLabelImage(img, withImage(o)), Contains("label 3") && Contains("background pixels"));
    o.drop_labels = {4};
    o.background = {5};
    CHECK_THROWS_WITH(tissueFromLabelImage(img, withImage(o)), Contains("label 3") && Contains("background"));
    o.background = {};
    o.drop_labels = {};
    o.crop = {0, 0, 5, 4};  // x 0..4: labels 1 and 2, and one column of 3
    const ImportResult r = tissueFromLabelImage(img, withImage(o));
    CHECK(labels(r) == std::vector<std::int64_t>{1, 2, 3});
    const auto areas = areasByLabel(r.tissue);
    CHECK(areas.at(1) == Approx(4.0));
    CHECK(areas.at(3) == Approx(4.0));
    // Pixel (i, j) is the unit square around (i, j): the crop keeps x from -0.5 to 4.5.
    double xmin = 1e300, xmax = -1e300;
    for (VertexId v : r.tissue.vertices())
      xmin = std::min(xmin, r.tissue.position(v).x()), xmax = std::max(xmax, r.tissue.position(v).x());
    CHECK(xmin == -0.5);
    CHECK(xmax == 4.5);
  }
  SECTION("a label in two pieces") {
    const LabelImage split = drawn({
        "2223",
        "3333",
        "2223",
    });
    CHECK_THROWS_WITH(tissueFromLabelImage(split, {}),
                      Contains("'drawn': label 2 is made of 2 disconnected pieces (of 3, 3 pixels; a pixel of "
                               "each: (0, 0), (0, 2))") &&
                          Contains("keep_pieces"));
    LabelImageOptions o;
    o.keep_pieces = true;
    const ImportResult r = tissueFromLabelImage(split, withImage(o));
    CHECK(labels(r) == std::vector<std::int64_t>{2, 2, 3});
    CHECK(validate(r.tissue).ok);
  }
}

TEST_CASE("pixel-diagonal contacts are bridged by one label, deterministically", "[io][label_image]") {
  // A checkerboard corner of labels 2 and 3 in the middle: 2 (the smaller) is joined across it.
  const LabelImage img = drawn({
      "3322",
      "3322",
      "2233",
      "2233",
  });
  CHECK_THROWS_WITH(tissueFromLabelImage(img, {}), Contains("label 3 is made of 2 disconnected pieces"));
  LabelImageOptions pieces;
  pieces.keep_pieces = true;
  const ImportResult r = tissueFromLabelImage(img, withImage(pieces));
  REQUIRE(validate(r.tissue).ok);
  const auto& label = r.tissue.cellProperties().get<std::int64_t>("label");
  std::vector<std::int64_t> got;
  for (CellId c : r.tissue.cells()) got.push_back(label[c]);
  CHECK(got == std::vector<std::int64_t>{2, 3, 3});  // 2 in one piece, 3 in two
  // The corner is split into two vertices a quarter pixel off it along the diagonal of the 3s: each 3 loses
  // two triangles of its corner pixel, each with a pixel edge as base and height 1/4: 1/8 each, 1/2 in all.
  const auto areas = areasByLabel(r.tissue);
  double area3 = 0;
  for (CellId c : r.tissue.cells())
    if (label[c] == 3) area3 += cellMeasure(r.tissue, c);
  CHECK(areas.at(2) == Approx(8.5));
  CHECK(area3 == Approx(7.5));
  // Labels 3 and 2 swapped: 2 still bridges.
  const LabelImage swapped = drawn({
      "2233",
      "2233",
      "3322",
      "3322",
  });
  const ImportResult s = tissueFromLabelImage(swapped, withImage(pieces));
  REQUIRE(validate(s.tissue).ok);
  CHECK(s.tissue.numCells() == 3);
  // A cell touching another only at a corner with background on both sides: split apart.
  const LabelImage corner = drawn({
      "..33",
      "..33",
      "22..",
      "22..",
  });
  const ImportResult t = tissueFromLabelImage(corner, {});
  REQUIRE(validate(t.tissue).ok);
  CHECK(t.tissue.numCells() == 2);
  CHECK(neighbourPairs(t.tissue, true).empty());
}

TEST_CASE("label image errors name the file, the label and the value", "[io][label_image]") {
  TempDir dir;
  const LabelImage img = drawn({"2233", "2233"});
  SECTION("one label") {
    CHECK_THROWS_WITH(tissueFromLabelImage(drawn({"22", "22"}), {}),
                      Contains("'drawn': the image holds one label only (2 in every pixel)"));
    CHECK_THROWS_WITH(tissueFromLabelImage(drawn({"10", "01"}), {}), Contains("no cells: every pixel is background"));
  }
  SECTION("voxel size") {
    LabelImageOptions o;
    o.voxel_size = {1.0, 0.0};
    CHECK_THROWS_WITH(tissueFromLabelImage(img, withImage(o)),
                      Contains("'drawn': voxel_size y = 0 must be a positive"));
    o.voxel_size = {-2.0, 1.0};
    CHECK_THROWS_WITH(tissueFromLabelImage(img, withImage(o)), Contains("voxel_size x = -2"));
    LabelImage bad = img;
    bad.spacing = {0, 1, 1};
    CHECK_THROWS_WITH(tissueFromLabelImage(bad, {}), Contains("pixel size in x is 0") && Contains("voxel_size"));
  }
  SECTION("3D") {
    LabelImage vol = img;
    vol.dims = {2, 2, 2};
    const ImportResult r = tissueFromLabelImage(vol, {});  // test_label_image_3d.cpp tests 3D images
    CHECK(r.tissue.dim() == 3);
    CHECK(r.tissue.numCells() == 2);
  }
  SECTION("crop and small_cells") {
    LabelImageOptions o;
    o.crop = {0, 0, 5, 1};
    CHECK_THROWS_WITH(tissueFromLabelImage(img, withImage(o)), Contains("crop 0, 0, 5, 1 is not a box"));
    o.crop = {};
    o.small_cells = "keep";
    CHECK_THROWS_WITH(tissueFromLabelImage(img, withImage(o)), Contains("small_cells must be drop or merge"));
  }
  SECTION("files") {
    LabelImage f = drawn({"2233", "2233"});
    f.spacing = {0.5, 0.5, 1};
    const std::string floats = dir.file("float.vti");
    writeVtkImage(f, floats, true);
    CHECK_THROWS_WITH(importTissue(floats),
                      Contains("'" + floats + "' holds float values: a label image holds integers"));
    LabelImage vol = f;
    vol.dims = {4, 1, 2};
    const std::string three = dir.file("vol.mha");
    writeVtkImage(vol, three);
    CHECK(importTissue(three).tissue.dim() == 3);  // more than one z layer: a 3D tissue
    LabelImageOptions only_images;
    only_images.min_cell_size = 3;
    const std::string ply = dir.file("cells.ply");
    std::ofstream(ply) << "ply\n";
    ImportOptions as_mesh = withImage(only_images);
    as_mesh.format = "morphographx";
    CHECK_THROWS_WITH(importTissue(ply, as_mesh), Contains("apply to label images only, not to morphographx"));
    const std::string missing = dir.file("missing.tif");
    CHECK_THROWS_WITH(importTissue(missing), Contains("no such file"));
    const std::string junk = dir.file("junk.mha");
    std::ofstream(junk) << "not an image\n";
    CHECK_THROWS_AS(importTissue(junk), InputError);
    // A good one: the pixel size from the file.
    const std::string good = dir.file("good.mha");
    writeVtkImage(f, good);
    const ImportResult r = importTissue(good);
    CHECK(r.tissue.numCells() == 2);
    const auto areas = areasByLabel(r.tissue);
    CHECK(areas.at(2) == Approx(1.0));  // 4 pixels of 0.5 x 0.5
    // VTK's MetaImage reader corrupts memory on 64-bit element types (docs/import.md): such a file is refused
    // by its header, before VTK reads it, naming the file and the type; the same file in 32 bits imports.
    const auto handMade = [&](const std::string& name, const std::string& type, std::size_t bytes) {
      const std::string path = dir.file(name);
      std::ofstream out(path, std::ios::binary);
      out << "ObjectType = Image\nNDims = 2\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
          << "DimSize = 4 2\nElementSpacing = 1 1\nElementType = " << type << "\nElementDataFile = LOCAL\n";
      for (const int label : {2, 2, 3, 3, 2, 2, 3, 3}) {
        const std::uint64_t value = static_cast<std::uint64_t>(label);
        out.write(reinterpret_cast<const char*>(&value), static_cast<std::streamsize>(bytes));  // little-endian
      }
      return path;
    };
    for (const std::string type : {"MET_LONG_LONG", "MET_ULONG_LONG"}) {
      const std::string wide = handMade("wide_" + type + ".mha", type, 8);
      CHECK_THROWS_WITH(importTissue(wide), Contains("'" + wide + "'") && Contains(type) &&
                                                Contains("store the labels in 32 bits or as a .vti file"));
      CHECK_THROWS_WITH(readLabelImage(wide), Contains(type));
    }
    CHECK(importTissue(handMade("narrow.mha", "MET_UINT", 4)).tissue.numCells() == 2);
  }
}

namespace {

// A random label image of `labels` labels in blobs (noise smoothed by a few majority votes over 3 x 3 pixels):
// many cells, pieces, diagonal contacts and background.
LabelImage blobs(std::uint32_t seed, std::int64_t w, std::int64_t h, int labels, int smoothing) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, labels - 1);
  LabelImage img;
  img.name = "blobs " + std::to_string(seed);
  img.dims = {w, h, 1};
  img.labels.resize(static_cast<std::size_t>(w * h));
  for (auto& l : img.labels) l = pick(rng);
  for (int pass = 0; pass < smoothing; ++pass) {
    std::vector<std::int64_t> next = img.labels;
    for (std::int64_t j = 0; j < h; ++j)
      for (std::int64_t i = 0; i < w; ++i) {
        std::map<std::int64_t, int> votes;
        for (std::int64_t dj = -1; dj <= 1; ++dj)
          for (std::int64_t di = -1; di <= 1; ++di)
            if (i + di >= 0 && i + di < w && j + dj >= 0 && j + dj < h)
              ++votes[img.labels[static_cast<std::size_t>((j + dj) * w + i + di)]];
        int most = 0;
        for (const auto& [l, n] : votes)
          if (n > most) most = n, next[static_cast<std::size_t>(j * w + i)] = l;
      }
    img.labels = std::move(next);
  }
  return img;
}

// What the image says directly, per label, in the import's rules (docs/import.md, "Algorithm"): its area,
// the shoelace sum over its boundary pixel edges, each end of an edge at a pinched corner moved a quarter pixel
// along the bridge's diagonal to the side the edge leaves the corner on; the pairs of labels sharing a pixel
// edge; the labels on the border or next to background.
struct ImageFacts {
  std::map<std::int64_t, double> area;
  std::set<std::pair<std::int64_t, std::int64_t>> pairs;
  std::set<std::int64_t> border;
};

ImageFacts factsOf(const LabelImage& img, const std::vector<std::int64_t>& background) {
  const std::int64_t w = img.dims[0], h = img.dims[1];
  constexpr std::int64_t kOut = std::numeric_limits<std::int64_t>::min();
  auto at = [&](std::int64_t i, std::int64_t j) {
    if (i < 0 || j < 0 || i >= w || j >= h) return kOut;
    const std::int64_t l = img.labels[static_cast<std::size_t>(j * w + i)];
    return std::find(background.begin(), background.end(), l) != background.end() ? kOut : l;
  };
  // Corner (x, y) is the lower left corner of pixel (x, y); an edge leaves it down (0), right (1), up (2) or
  // left (3).
  auto corner = [&](std::int64_t x, std::int64_t y, int axis) {
    const std::int64_t a = at(x - 1, y - 1), b = at(x, y - 1), c = at(x - 1, y), d = at(x, y);
    const bool ad = a == d && b != a && c != a, bc = b == c && a != b && d != b;
    const double px = static_cast<double>(x), py = static_cast<double>(y), q = 0.25;
    if (!ad && !bc) return std::array<double, 2>{px, py};
    const bool use_ad = ad && bc ? (b == kOut ? true : a == kOut ? false : a < b) : ad;
    if (use_ad) return axis <= 1 ? std::array<double, 2>{px + q, py - q} : std::array<double, 2>{px - q, py + q};
    return axis == 0 || axis == 3 ? std::array<double, 2>{px - q, py - q} : std::array<double, 2>{px + q, py + q};
  };
  ImageFacts f;
  for (std::int64_t j = -1; j <= h; ++j)
    for (std::int64_t i = -1; i <= w; ++i) {
      const std::int64_t a = at(i, j);
      for (const std::int64_t b : {at(i + 1, j), at(i, j + 1)}) {
        if (a == b || (a == kOut && b == kOut)) continue;
        if (a == kOut || b == kOut) f.border.insert(a == kOut ? b : a);
        else f.pairs.insert(std::minmax(a, b));
      }
      if (a == kOut) continue;
      // The pixel's edges counter-clockwise: bottom, right, top, left, each from (corner, axis leaving it) to
      // (corner, axis), and the pixel across it.
      struct Side {
        std::int64_t x0, y0;
        int axis0;
        std::int64_t x1, y1;
        int axis1;
        std::int64_t other;
      };
      const Side sides[4] = {{i, j, 1, i + 1, j, 3, at(i, j - 1)},
                             {i + 1, j, 2, i + 1, j + 1, 0, at(i + 1, j)},
                             {i + 1, j + 1, 3, i, j + 1, 1, at(i, j + 1)},
                             {i, j + 1, 0, i, j, 2, at(i - 1, j)}};
      for (const Side& s : sides) {
        if (s.other == a) continue;
        const auto p = corner(s.x0, s.y0, s.axis0), q = corner(s.x1, s.y1, s.axis1);
        f.area[a] += 0.5 * (p[0] * q[1] - q[0] * p[1]);
      }
    }
  return f;
}

// Everything of a tissue, to compare two imports bit for bit.
std::string dump(const Tissue& t) {
  std::ostringstream out;
  out << std::hexfloat;
  for (VertexId v : t.vertices()) out << t.position(v).x() << ' ' << t.position(v).y() << ';';
  const auto& label = t.cellProperties().get<std::int64_t>("label");
  for (CellId c : t.cells()) {
    out << '\n' << label[c] << ':';
    for (VertexId v : t.topology().faceVertices(t.cellFace(c))) out << ' ' << v.index();
  }
  return out.str();
}

}  // namespace

TEST_CASE("2D imports keep each label's pixel area and its pixel-edge neighbours", "[io][label_image]") {
  int imported = 0;
  for (std::uint32_t seed = 1; seed <= 60; ++seed) {
    const std::int64_t w = 8 + seed % 23, h = 5 + (seed * 7) % 29;
    const LabelImage img = blobs(seed, w, h, 3 + static_cast<int>(seed % 5), static_cast<int>(seed % 3));
    LabelImageOptions options;
    options.keep_pieces = true;
    options.background = seed % 2 ? std::vector<std::int64_t>{0} : std::vector<std::int64_t>{};
    INFO("seed " << seed);
    ImportResult r{Tissue(2, Embedding::Planar), {}};
    try {
      r = tissueFromLabelImage(img, withImage(options));
    } catch (const InputError& e) {
      CHECK_THAT(e.what(), Contains("has a hole"));  // the one error random blobs may give
      continue;
    }
    ++imported;
    REQUIRE(validate(r.tissue).ok);
    const ImageFacts want = factsOf(img, options.background);
    std::map<std::int64_t, double> area;  // summed over the pieces of a label
    const auto& label = r.tissue.cellProperties().get<std::int64_t>("label");
    for (CellId c : r.tissue.cells()) area[label[c]] += cellMeasure(r.tissue, c);
    REQUIRE(area.size() == want.area.size());
    for (const auto& [l, a] : want.area) CHECK(area.at(l) == Approx(a).margin(1e-9));
    std::set<std::pair<std::int64_t, std::int64_t>> pairs;
    for (const auto& [pair, length] : neighbourPairs(r.tissue, true))
      if (pair.first != pair.second) pairs.insert(pair);
    CHECK(pairs == want.pairs);
    CHECK(boundaryCells(r.tissue, true) == want.border);
  }
  CHECK(imported >= 20);
}

TEST_CASE("2D imports are the same bit for bit on one thread and on two", "[io][label_image]") {
  const int threads = omp_get_max_threads();
  const LabelImage voronoi = rasterise(voronoi200(), 512);
  for (const bool merge : {false, true})
    for (const double simplify : {0.0, 1.0, 2.5}) {
      LabelImageOptions options;  // merged: the background too, and more cells into their neighbours
      options.keep_pieces = true;
      if (merge) options.background = {}, options.min_cell_size = 1500, options.small_cells = "merge";
      omp_set_num_threads(1);
      const std::string one = dump(tissueFromLabelImage(voronoi, withImage(options, simplify)).tissue);
      omp_set_num_threads(2);
      const std::string two = dump(tissueFromLabelImage(voronoi, withImage(options, simplify)).tissue);
      INFO("merge " << merge << ", simplify " << simplify);
      CHECK(one == two);
    }
  omp_set_num_threads(threads);
}

TEST_CASE("2D imports whose walls start, end and pinch on every row (the sweep's two blocks of rows)",
          "[io][label_image]") {
  // The corner graph is swept in two blocks of rows at once and joined (docs/import.md, "Algorithm"), the
  // split about halfway down the runs: walls crossing it, ending or starting on every row, and pinched corners
  // on every row must come out as one sweep makes them.
  const int threads = omp_get_max_threads();
  for (const std::int64_t h : {6, 7, 8, 9, 16, 23, 64}) {
    // Left: diagonal bands of labels 10, 11, 12, pinched at every pixel corner; right: stripes 2 pixels wide,
    // stripe s cut in two at row 1 + s mod (h - 1).
    const std::int64_t w_diag = 12, n_stripes = h, w = w_diag + 2 * n_stripes;
    LabelImage img;
    img.name = "rows " + std::to_string(h);
    img.dims = {w, h, 1};
    img.labels.resize(static_cast<std::size_t>(w * h));
    for (std::int64_t j = 0; j < h; ++j)
      for (std::int64_t i = 0; i < w; ++i) {
        const std::int64_t s = (i - w_diag) / 2;
        img.labels[static_cast<std::size_t>(j * w + i)] =
            i < w_diag ? 10 + (i + j) % 3 : 100 + 2 * s + (j >= 1 + s % (h - 1) ? 1 : 0);
      }
    LabelImageOptions options;
    options.keep_pieces = true;
    INFO("h " << h);
    omp_set_num_threads(1);
    const ImportResult one = tissueFromLabelImage(img, withImage(options));
    omp_set_num_threads(2);
    const ImportResult two = tissueFromLabelImage(img, withImage(options));
    omp_set_num_threads(threads);
    CHECK(dump(one.tissue) == dump(two.tissue));
    REQUIRE(validate(two.tissue).ok);
    const ImageFacts want = factsOf(img, options.background);
    std::map<std::int64_t, double> area;
    const auto& label = two.tissue.cellProperties().get<std::int64_t>("label");
    for (CellId c : two.tissue.cells()) area[label[c]] += cellMeasure(two.tissue, c);
    REQUIRE(area.size() == want.area.size());
    for (const auto& [l, a] : want.area) CHECK(area.at(l) == Approx(a).margin(1e-9));
    std::set<std::pair<std::int64_t, std::int64_t>> pairs;
    for (const auto& [pair, length] : neighbourPairs(two.tissue, true))
      if (pair.first != pair.second) pairs.insert(pair);
    CHECK(pairs == want.pairs);
    CHECK(boundaryCells(two.tissue, true) == want.border);

    // Stripes alone, 3 pixels wide, uncut: every wall one edge from the bottom row to the top one, across the
    // split; simplified (at simplify 0 the distance test's rounding may keep a corner of a long straight wall,
    // docs/import.md), n rectangles have 2 (n + 1) corners.
    LabelImage stripes;
    stripes.name = "stripes " + std::to_string(h);
    stripes.dims = {3 * n_stripes, h, 1};
    for (std::int64_t j = 0; j < h; ++j)
      for (std::int64_t i = 0; i < 3 * n_stripes; ++i) stripes.labels.push_back(2 + i / 3);
    const ImportResult r = tissueFromLabelImage(stripes, withImage({}, 1.0));
    REQUIRE(validate(r.tissue).ok);
    CHECK(r.tissue.numCells() == static_cast<std::size_t>(n_stripes));
    CHECK(r.tissue.numVertices() == static_cast<std::size_t>(2 * (n_stripes + 1)));
    for (CellId c : r.tissue.cells()) {
      CHECK(r.tissue.topology().faceVertices(r.tissue.cellFace(c)).size() == 4);
      CHECK(cellMeasure(r.tissue, c) == Approx(3.0 * static_cast<double>(h)));
    }
  }
}

namespace {

// The image's labels, label l stored as f(l): as a MetaImage of element type `met` (T: its C++ type), or, for
// 64-bit types (which VTK 9.1's MetaImage reader corrupts memory on), as VTK image data of T (`met` names it).
template <typename T, typename F>
void writeTypedImage(const LabelImage& img, const std::string& path, const char* met, F f) {
  if constexpr (sizeof(T) == 8) {
    auto data = vtkSmartPointer<vtkImageData>::New();
    data->SetDimensions(static_cast<int>(img.dims[0]), static_cast<int>(img.dims[1]), 1);
    data->SetSpacing(img.spacing.data());
    data->SetOrigin(img.origin.data());
    auto values = vtkSmartPointer<vtkAOSDataArrayTemplate<T>>::New();
    values->SetName(met);
    values->SetNumberOfTuples(static_cast<vtkIdType>(img.labels.size()));
    for (std::size_t k = 0; k < img.labels.size(); ++k)
      values->SetValue(static_cast<vtkIdType>(k), static_cast<T>(f(img.labels[k])));
    data->GetPointData()->SetScalars(values);
    auto w = vtkSmartPointer<vtkXMLImageDataWriter>::New();
    w->SetFileName(path.c_str());
    w->SetInputData(data);
    REQUIRE(w->Write() == 1);
    return;
  }
  std::ofstream out(path, std::ios::binary);
  out.precision(17);
  out << "ObjectType = Image\nNDims = 2\nBinaryData = True\nBinaryDataByteOrderMSB = False\nDimSize = "
      << img.dims[0] << " " << img.dims[1] << "\nElementSpacing = " << img.spacing[0] << " " << img.spacing[1]
      << "\nOffset = " << img.origin[0] << " " << img.origin[1] << "\nElementType = " << met
      << "\nElementDataFile = LOCAL\n";
  for (const std::int64_t l : img.labels) {
    const T v = static_cast<T>(f(l));
    out.write(reinterpret_cast<const char*>(&v), sizeof v);
  }
}

}  // namespace

TEST_CASE("a 2D label image file imports the same whatever integer type stores its labels", "[io][label_image]") {
  TempDir dir;
  const LabelImage img = rasterise(voronoi200(), 128);  // labels 2..201, 0 outside the cells
  // Each type: the labels moved into its range (negative ones where signed), the outside a value of its own.
  auto check = [&]<typename T>(T, const char* met, std::int64_t outside, std::int64_t scale, std::int64_t shift) {
    auto f = [&](std::int64_t l) { return l == 0 ? outside : l * scale + shift; };
    const std::string path = dir.file(std::string("cells_") + met + (sizeof(T) == 8 ? ".vti" : ".mha"));
    writeTypedImage<T>(img, path, met, f);
    LabelImage stored = img;  // the reference: the same labels through the 64-bit array
    for (std::int64_t& l : stored.labels) l = f(l);
    for (const double simplify : {0.0, 1.0}) {
      LabelImageOptions options;
      options.background = {outside};
      options.keep_pieces = true;
      options.crop = {3, 5, 120, 110};
      const ImportResult from_file = importTissue(path, withImage(options, simplify));
      const ImportResult from_array = tissueFromLabelImage(stored, withImage(options, simplify));
      INFO(met << ", simplify " << simplify);
      CHECK(from_file.tissue.numCells() > 150);
      CHECK(dump(from_file.tissue) == dump(from_array.tissue));
      CHECK(from_file.report.notes == from_array.report.notes);
      const auto& label = from_file.tissue.cellProperties().get<std::int64_t>("label");
      std::set<std::int64_t> labels(label.values().begin(), label.values().end());
      std::set<std::int64_t> want;
      for (std::int64_t j = 5; j < 110; ++j)
        for (std::int64_t i = 3; i < 120; ++i)
          if (const std::int64_t l = img.labels[static_cast<std::size_t>(j * 128 + i)]; l != 0) want.insert(f(l));
      CHECK(labels == want);
    }
  };
  check(std::uint8_t{}, "MET_UCHAR", 255, 1, 0);
  check(std::int8_t{}, "MET_CHAR", -128, 1, -100);
  check(std::int16_t{}, "MET_SHORT", 0, 100, -10001);
  check(std::uint16_t{}, "MET_USHORT", 0, 300, 0);
  check(std::int32_t{}, "MET_INT", 1, 1000000, -100000000);
  check(std::uint32_t{}, "MET_UINT", 0, 20000000, 0);
  check(std::int64_t{}, "int64", -1, 1000000000000, -100000000000000);
  check(std::uint64_t{}, "uint64", 0, 1000000000000000, 0);
  // An unsigned 64-bit label beyond a signed one: refused, naming the file, the pixel and the label.
  const std::string big = dir.file("big.vti");
  writeTypedImage<std::uint64_t>(img, big, "uint64",
                                [](std::int64_t l) { return l == 0 ? 0 : (std::uint64_t{1} << 63) + l; });
  std::size_t first = 0;  // the first pixel of a cell
  while (img.labels[first] == 0) ++first;
  const std::string message = "pixel " + std::to_string(first) + " has label " +
                              std::to_string((std::uint64_t{1} << 63) + static_cast<std::uint64_t>(img.labels[first]));
  CHECK_THROWS_WITH(importTissue(big, withImage({})),
                    Contains("big.vti") && Contains(message) && Contains("beyond a 64-bit signed integer"));
}
