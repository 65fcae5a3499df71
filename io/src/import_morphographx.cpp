// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// MorphoGraphX PLY cell meshes and cell graphs (docs/import.md).
//
// A cell is the set of triangles carrying its label; the shared core
// (labelled_surface.hpp) checks that each is a disk and builds the sheet of
// their outlines. Here: reading the file, and the `parent` lineage labels.

#include <algorithm>
#include <cmath>

#include "labelled_surface.hpp"
#include "ply_mesh_columns.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/ply.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::io {

namespace {

using detail::Label;
using detail::LabelledSurface;

// The file, read into plain arrays; MorphoGraphX's vertex `parent` beside.
LabelledSurface readMesh(const std::string& path, std::vector<Label>& vertex_parent) {
  const PlyFile ply = PlyFile::read(path);
  LabelledSurface m;
  m.path = path;
  const PlyColumn& vl = ply.integerScalar("vertex", "label");
  const std::size_t nv = ply.count("vertex");
  m.positions = detail::plyPositions(ply, path);
  m.vertex_label.resize(nv);
  for (std::size_t i = 0; i < nv; ++i) m.vertex_label[i] = static_cast<Label>(vl.values[i]);
  if (ply.hasProperty("vertex", "parent")) {
    const PlyColumn& vp = ply.integerScalar("vertex", "parent");
    vertex_parent.assign(vp.values.begin(), vp.values.end());
  }
  const PlyColumn& fv = detail::plyFaceVertexList(ply, path);
  const PlyColumn& fl = ply.integerScalar("face", "label");
  const std::size_t nf = ply.count("face");
  m.face_offsets = fv.offsets;
  m.face_vertices.resize(fv.values.size());
  m.face_label.resize(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    m.face_label[f] = static_cast<Label>(fl.values[f]);
    auto where = [&] {  // built only for an error
      return "'" + path + "' face " + std::to_string(f) + " (cell label " + std::to_string(m.face_label[f]) + ")";
    };
    const std::size_t n = m.face_offsets[f + 1] - m.face_offsets[f];
    if (n < 3) throw InputError(where() + ": has " + std::to_string(n) + " vertices, a face needs at least 3");
    for (std::size_t k = m.face_offsets[f]; k < m.face_offsets[f + 1]; ++k) {
      const double v = fv.values[k];
      if (v < 0 || v >= double(nv))
        throw InputError(where() + ": vertex index " + std::to_string(static_cast<long long>(v)) +
                         " is out of range (the file has " + std::to_string(nv) + " vertices, 0.." +
                         std::to_string(nv == 0 ? 0 : nv - 1) + ")");
      m.face_vertices[k] = static_cast<Index>(v);
    }
    for (std::size_t a = m.face_offsets[f]; a < m.face_offsets[f + 1]; ++a)
      for (std::size_t b = a + 1; b < m.face_offsets[f + 1]; ++b)
        if (m.face_vertices[a] == m.face_vertices[b])
          throw InputError(where() + ": uses vertex " + std::to_string(m.face_vertices[a]) +
                           " twice (a degenerate face)");
    if (m.face_label[f] <= 0)
      throw InputError(where() + ": label " + std::to_string(m.face_label[f]) +
                       " is no cell (MorphoGraphX cell labels are positive)");
  }
  return m;
}

}  // namespace

bool isMorphoGraphXMesh(const std::string& path) {
  const PlyHeader h = readPlyHeader(path);
  const PlyElement* v = h.element("vertex");
  const PlyElement* f = h.element("face");
  return v && f && v->property("label") && f->property("label");
}

ImportResult importMorphoGraphX(const std::string& path, const ImportOptions& options) {
  detail::checkImportOptions(options);
  std::vector<Label> vertex_parent;  // empty without a parent property
  LabelledSurface m = readMesh(path, vertex_parent);
  ImportResult result{Tissue(2, Embedding::Surface), {}};
  ImportReport& report = result.report;
  report.path = path;
  report.format = "morphographx";
  report.file_vertices = m.positions.size();
  report.file_faces = m.numFaces();
  detail::LabelledSheet sheet = detail::buildLabelledSheet(m, options, report);
  result.tissue = std::move(sheet.tissue);
  const detail::SheetCells& cells = sheet.cells;

  const bool has_parent = !vertex_parent.empty();
  PropertyColumn<std::int64_t>* parent =
      has_parent ? &result.tissue.cellProperties().add<std::int64_t>("parent", 0) : nullptr;
  std::size_t without_centre = 0;
  for (std::size_t c = 0; parent && c < cells.labels.size(); ++c) {
    Index centre = kInvalidIndex;
    for (Index f : cells.faces[c])
      for (Index v : m.face(f))
        if (centre == kInvalidIndex && m.vertex_label[v] == cells.labels[c]) centre = v;
    if (centre == kInvalidIndex) {
      ++without_centre;
      continue;
    }
    (*parent)[CellId(static_cast<Index>(c))] = vertex_parent[centre];
  }
  report.notes.push_back("cell properties: label" + std::string(has_parent ? ", parent" : "") +
                         " (from the file's vertex and face labels)");
  if (without_centre > 0)
    report.notes.push_back(std::to_string(without_centre) +
                           " cells have no centre vertex carrying their label: parent 0 (unknown)");
  if (const std::size_t unused = detail::unusedVertices(m); unused > 0)
    report.notes.push_back(std::to_string(unused) + " vertices of the file are in no face: ignored");
  return result;
}

std::vector<std::pair<std::int64_t, std::int64_t>> MorphoGraphXCellGraph::neighbourPairs() const {
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  for (auto [a, b] : edges) pairs.emplace_back(std::min(a, b), std::max(a, b));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

MorphoGraphXCellGraph readMorphoGraphXCellGraph(const std::string& path) {
  const PlyFile ply = PlyFile::read(path);
  MorphoGraphXCellGraph g;
  const PlyColumn& labels = ply.integerScalar("vertex", "label");
  g.labels.assign(labels.values.begin(), labels.values.end());
  if (ply.hasProperty("vertex", "Geometry/Area")) g.areas = ply.scalar("vertex", "Geometry/Area").values;
  std::vector<std::int64_t> sorted = g.labels;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i] == sorted[i - 1]) {
      const auto first = std::find(g.labels.begin(), g.labels.end(), sorted[i]) - g.labels.begin();
      const auto second = std::find(g.labels.begin() + first + 1, g.labels.end(), sorted[i]) - g.labels.begin();
      throw InputError("'" + path + "' vertices " + std::to_string(first) + " and " + std::to_string(second) +
                       ": label " + std::to_string(sorted[i]) + " is listed twice");
    }
  const PlyColumn& source = ply.integerScalar("edge", "source");
  const PlyColumn& target = ply.integerScalar("edge", "target");
  for (std::size_t e = 0; e < source.values.size(); ++e) {
    const auto a = static_cast<std::int64_t>(source.values[e]), b = static_cast<std::int64_t>(target.values[e]);
    for (std::int64_t l : {a, b})
      if (!std::binary_search(sorted.begin(), sorted.end(), l))
        throw InputError("'" + path + "' edge " + std::to_string(e) + ": " + std::to_string(l) +
                         " is not the label of a listed cell");
    if (a == b)
      throw InputError("'" + path + "' edge " + std::to_string(e) + ": cell label " + std::to_string(a) +
                       " is its own neighbour");
    g.edges.emplace_back(a, b);
  }
  return g;
}

}  // namespace tessella::io
