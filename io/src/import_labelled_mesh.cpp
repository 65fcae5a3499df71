// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Generic labelled meshes (docs/import.md, format `labelled_mesh`): a polygon
// surface mesh in PLY, OBJ or VTK PolyData (.vtp) whose faces carry the label
// of the cell they lie in. One label per face: each label's faces are a patch
// of one surface, and the patches' outlines a curved sheet. Two labels per
// face (the cells on either side, <= 0 for the outside): each label's faces
// bound a closed cell, a 3D tissue. Both go through the cell-complex core
// (cell_complex_core.hpp), which classifies, orients and builds.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "cell_complex_core.hpp"
#include "ply_mesh_columns.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/ply.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "vtu_file.hpp"

namespace tessella::io {

namespace {

using detail::ComplexFile;
using detail::fmtPoint;
using detail::Label;

// A mesh whose faces carry one or two labels, every index checked.
struct LabelledFaces {
  std::string path;
  std::vector<Vec3> positions;
  std::vector<std::size_t> offsets{0};
  std::vector<Index> vertices;
  std::vector<Label> first, second;  // second empty: one label per face
  std::string label_source;          // "face property 'label'", ...
  const char* face_noun = "face";    // "polygon" in a .vtp
  std::size_t numFaces() const { return offsets.size() - 1; }
};

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// The label names asked for: one name, or two separated by a comma (the
// cells in front of and behind each face).
std::vector<std::string> requestedNames(const std::string& option) {
  std::vector<std::string> names;
  std::string rest = option;
  for (std::size_t comma; (comma = rest.find(',')) != std::string::npos; rest = rest.substr(comma + 1))
    names.push_back(rest.substr(0, comma));
  names.push_back(rest);
  for (std::string& n : names) {
    while (!n.empty() && n.front() == ' ') n.erase(n.begin());
    while (!n.empty() && n.back() == ' ') n.pop_back();
    if (n.empty() || names.size() > 2)
      throw InputError("label_array '" + option + "' must name one array, or two separated by a comma");
  }
  return names;
}

// A label value as read (a double: PLY and VTK values); InputError unless
// it is an integer. `where()` builds the message's start, only on error.
template <typename Where>
Label labelValue(double v, Where where) {
  if (!(std::isfinite(v) && v == std::floor(v) && std::abs(v) < 9007199254740992.0))
    throw InputError(where() + ": label " + formatNumber(v) + " is not an integer");
  return static_cast<Label>(v);
}

// Checks a face's vertex indices (already in range) for repeats and count.
template <typename Where>
void checkFaceLoop(const LabelledFaces& m, std::size_t f, Where where) {
  const std::size_t n = m.offsets[f + 1] - m.offsets[f];
  if (n < 3) throw InputError(where() + ": has " + std::to_string(n) + " vertices, a face needs at least 3");
  for (std::size_t a = m.offsets[f]; a < m.offsets[f + 1]; ++a)
    for (std::size_t b = a + 1; b < m.offsets[f + 1]; ++b)
      if (m.vertices[a] == m.vertices[b])
        throw InputError(where() + ": uses vertex " + std::to_string(m.vertices[a]) + " twice (a degenerate face)");
}

std::string faceWhere(const LabelledFaces& m, std::size_t f) {
  std::string w = "'" + m.path + "' " + m.face_noun + " " + std::to_string(f);
  if (f < m.first.size()) {
    w += m.second.empty() ? " (cell label " + std::to_string(m.first[f]) + ")"
                          : " (cell labels " + std::to_string(m.first[f]) + " and " + std::to_string(m.second[f]) + ")";
  }
  return w;
}

std::string outOfRange(double v, std::size_t n) {
  return "vertex index " + std::to_string(static_cast<long long>(v)) + " is out of range (the file has " +
         std::to_string(n) + " vertices" + (n == 0 ? "" : ", 0.." + std::to_string(n - 1)) + ")";
}

// --- PLY -------------------------------------------------------------------------

constexpr const char* kDefaultSingle[] = {"label", "cell_label", "cell_id"};
constexpr const char* kDefaultPair[] = {"label_front", "label_back"};

LabelledFaces readPly(const std::string& path, const std::string& label_array) {
  const PlyFile ply = PlyFile::read(path);
  LabelledFaces m;
  m.path = path;
  const std::size_t nv = ply.count("vertex");
  const std::size_t nf = ply.count("face");  // InputError naming the file when there is no face element
  m.positions = detail::plyPositions(ply, path);
  // The label properties: asked for, or the first default present.
  std::vector<std::string> names;
  if (!label_array.empty()) {
    names = requestedNames(label_array);
  } else {
    for (const char* n : kDefaultSingle)
      if (names.empty() && ply.hasProperty("face", n)) names = {n};
    if (names.empty() && ply.hasProperty("face", kDefaultPair[0]) && ply.hasProperty("face", kDefaultPair[1]))
      names = {kDefaultPair[0], kDefaultPair[1]};
  }
  bool missing = names.empty();
  for (const std::string& n : names) missing = missing || !ply.hasProperty("face", n);
  if (missing) {
    std::string present;
    for (const PlyProperty& p : ply.header().element("face")->properties)
      present += (present.empty() ? "" : ", ") + p.name;
    throw InputError("'" + path + "': element 'face' has no cell label property " +
                     (label_array.empty() ? std::string("(looked for label, cell_label, cell_id, or the pair "
                                                        "label_front, label_back; label_array names another)")
                                          : "'" + label_array + "'") +
                     "; it has " + (present.empty() ? std::string("none") : present));
  }
  std::vector<const PlyColumn*> label_columns;
  for (const std::string& n : names) {
    const PlyColumn& c = ply.column("face", n);
    if (c.is_list)
      throw InputError("'" + path + "': face property '" + n + "' is a list, expected one integer label per face");
    label_columns.push_back(&c);
  }
  const PlyColumn& fv = detail::plyFaceVertexList(ply, path);
  m.offsets = fv.offsets;
  m.vertices.resize(fv.values.size());
  for (std::size_t f = 0; f < nf; ++f) {
    auto bare = [&](std::size_t a) { return "'" + path + "' face " + std::to_string(f) + " ('" + names[a] + "')"; };
    m.first.push_back(labelValue(label_columns[0]->values[f], [&] { return bare(0); }));
    if (names.size() == 2) m.second.push_back(labelValue(label_columns[1]->values[f], [&] { return bare(1); }));
    auto where = [&] { return faceWhere(m, f); };
    for (std::size_t k = m.offsets[f]; k < m.offsets[f + 1]; ++k) {
      const double v = fv.values[k];
      if (v < 0 || v >= double(nv)) throw InputError(where() + ": " + outOfRange(v, nv));
      m.vertices[k] = static_cast<Index>(v);
    }
    checkFaceLoop(m, f, where);
  }
  m.label_source = "face propert" + std::string(names.size() == 2 ? "ies '" + names[0] + "', '" + names[1] + "'"
                                                                   : "y '" + names[0] + "'");
  return m;
}

// --- OBJ -------------------------------------------------------------------------

// Wavefront OBJ: `v x y z [w]`, `f a b c ...` (1-based, negative = relative,
// `a/t/n` forms), the label of each face from the last `g` statement before
// it (label_array may pick `o` or `usemtl` instead): one integer name, or two
// (the cells on either side). Other statements (vt, vn, s, mtllib, ...) are ignored.
LabelledFaces readObj(const std::string& path, const std::string& label_array) {
  const std::string keyword = label_array.empty() ? "g" : label_array;
  if (keyword != "g" && keyword != "o" && keyword != "usemtl")
    throw InputError("'" + path + "': label_array '" + label_array +
                     "' names no OBJ label statement (g, o or usemtl)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "': no such file or not readable");
  LabelledFaces m;
  m.path = path;
  std::vector<Label> current;
  std::size_t line_no = 0, label_arity = 0;
  std::string line;
  auto number = [&](std::string_view tok, double& out) {
    const char* end = tok.data() + tok.size();
    auto [p, ec] = std::from_chars(tok.data(), end, out);
    return ec == std::errc() && p == end;
  };
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string at = "'" + path + "' line " + std::to_string(line_no);
    std::vector<std::string_view> tok;
    for (std::size_t i = 0; i < line.size();) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      if (i >= line.size() || line[i] == '#') break;
      const std::size_t j = i;
      while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      tok.emplace_back(line.data() + j, i - j);
    }
    if (tok.empty()) continue;
    if (tok[0] == "v") {
      double c[3];
      if (tok.size() < 4 || tok.size() > 5)
        throw InputError(at + ": a vertex needs 3 coordinates (4 with w), got " + std::to_string(tok.size() - 1));
      for (int k = 0; k < 3; ++k)
        if (!number(tok[1 + k], c[k]) || !std::isfinite(c[k]))
          throw InputError(at + " (vertex " + std::to_string(m.positions.size()) + "): coordinate " +
                           quotedToken(tok[1 + k]) + " is not a finite number");
      m.positions.emplace_back(c[0], c[1], c[2]);
    } else if (tok[0] == keyword) {
      current.clear();
      for (std::size_t k = 1; k < tok.size(); ++k) {
        long long l = 0;
        auto [p, ec] = std::from_chars(tok[k].data(), tok[k].data() + tok[k].size(), l);
        if (ec != std::errc() || p != tok[k].data() + tok[k].size())
          throw InputError(at + ": " + keyword + " name " + quotedToken(tok[k]) +
                           " is not an integer cell label (the labelled_mesh convention: '" + keyword +
                           " LABEL' before a cell's faces, or '" + keyword + " LABEL_FRONT LABEL_BACK')");
        current.push_back(l);
      }
      if (current.empty() || current.size() > 2)
        throw InputError(at + ": '" + keyword +
                         "' needs one integer cell label, or two (the cells on either side), got " +
                         std::to_string(current.size()));
    } else if (tok[0] == "f") {
      const std::size_t f = m.numFaces();
      if (current.empty())
        throw InputError(at + " (face " + std::to_string(f) + "): a face before any '" + keyword +
                         " LABEL' statement: its cell label is unknown");
      if (label_arity == 0) label_arity = current.size();
      if (current.size() != label_arity)
        throw InputError(at + " (face " + std::to_string(f) + "): " + std::to_string(current.size()) +
                         " cell label(s), but the faces before have " + std::to_string(label_arity));
      m.first.push_back(current[0]);
      if (label_arity == 2) m.second.push_back(current[1]);
      const std::string labels =
          label_arity == 2 ? "s " + std::to_string(current[0]) + " and " + std::to_string(current[1])
                           : " " + std::to_string(current[0]);
      auto where = [&] { return at + " (face " + std::to_string(f) + ", cell label" + labels + ")"; };
      for (std::size_t k = 1; k < tok.size(); ++k) {
        const std::string_view index = tok[k].substr(0, tok[k].find('/'));
        long long i = 0;
        auto [p, ec] = std::from_chars(index.data(), index.data() + index.size(), i);
        if (ec != std::errc() || p != index.data() + index.size() || i == 0)
          throw InputError(where() + ": vertex reference " + quotedToken(tok[k]) + " is no vertex index");
        const long long n = static_cast<long long>(m.positions.size());
        const long long v = i > 0 ? i - 1 : n + i;  // negative: relative to the vertices so far
        if (v < 0 || v >= n)
          throw InputError(where() + ": vertex index " + std::to_string(i) + " is out of range (" + std::to_string(n) +
                           " vertices defined so far, 1.." + std::to_string(n) + ")");
        m.vertices.push_back(static_cast<Index>(v));
      }
      m.offsets.push_back(m.vertices.size());
      checkFaceLoop(m, f, where);
    }
  }
  if (in.bad()) throw InputError("cannot read '" + path + "': read error after line " + std::to_string(line_no));
  m.label_source = "OBJ '" + keyword + "' statements";
  return m;
}

// --- VTK PolyData ------------------------------------------------------------------

LabelledFaces readVtp(const std::string& path, const std::string& label_array) {
  vtkSmartPointer<vtkPolyData> data = detail::readPolyDataFile(path);
  detail::checkPolyArrays(data, path);
  const std::string file = "'" + path + "'";
  if (data->GetNumberOfVerts() + data->GetNumberOfLines() + data->GetNumberOfStrips() > 0)
    throw InputError(file + " has " + std::to_string(data->GetNumberOfVerts()) + " vertex, " +
                     std::to_string(data->GetNumberOfLines()) + " line and " +
                     std::to_string(data->GetNumberOfStrips()) +
                     " strip cells: a labelled mesh holds polygons (triangles, quads, ...) only");
  vtkCellData* cd = data->GetCellData();
  std::vector<std::string> names;
  if (!label_array.empty()) {
    names = requestedNames(label_array);
  } else {
    for (const char* n : kDefaultSingle)
      if (names.empty() && cd->GetArray(n)) names = {n};
    if (names.empty() && cd->GetArray(kDefaultPair[0]) && cd->GetArray(kDefaultPair[1]))
      names = {kDefaultPair[0], kDefaultPair[1]};
  }
  bool missing = names.empty();
  for (const std::string& n : names) missing = missing || !cd->GetArray(n.c_str());
  if (missing) {
    std::string present;
    for (int i = 0; i < cd->GetNumberOfArrays(); ++i)
      present += (present.empty() ? "" : ", ") + std::string(cd->GetArrayName(i) ? cd->GetArrayName(i) : "(unnamed)");
    throw InputError(file + " has no cell-data array " +
                     (label_array.empty() ? std::string("label, cell_label, cell_id, or the pair label_front, "
                                                        "label_back (label_array names another)")
                                          : "'" + label_array + "'") +
                     " naming each polygon's cell (it has " + (present.empty() ? std::string("none") : present) + ")");
  }
  // One array of one component, two arrays of one, or one array of two components.
  std::vector<std::pair<vtkDataArray*, int>> sources;  // array, component
  for (const std::string& n : names) {
    vtkDataArray* a = cd->GetArray(n.c_str());
    const int components = a->GetNumberOfComponents();
    if (components == 2 && names.size() == 1) {
      sources = {{a, 0}, {a, 1}};
    } else if (components != 1) {
      throw InputError(file + ": cell-data array '" + n + "' has " + std::to_string(components) +
                       " components, expected one label per polygon (or two: the cells on either side)");
    } else {
      sources.emplace_back(a, 0);
    }
  }
  LabelledFaces m;
  m.path = path;
  m.face_noun = "polygon";
  const vtkIdType np = data->GetPoints() ? data->GetNumberOfPoints() : 0;
  m.positions.resize(static_cast<std::size_t>(np));
  for (vtkIdType i = 0; i < np; ++i) {
    double p[3];
    data->GetPoint(i, p);
    m.positions[static_cast<std::size_t>(i)] = Vec3(p[0], p[1], p[2]);
    if (!m.positions[static_cast<std::size_t>(i)].allFinite())
      throw InputError(file + " point " + std::to_string(i) + ": position " +
                       fmtPoint(m.positions[static_cast<std::size_t>(i)]) + " is not finite");
  }
  vtkCellArray* polys = data->GetPolys();
  const vtkIdType nf = polys ? polys->GetNumberOfCells() : 0;
  for (const auto& [a, c] : sources)
    if (a->GetNumberOfTuples() != nf)
      throw InputError(file + ": cell-data array '" + std::string(a->GetName()) + "' has " +
                       std::to_string(a->GetNumberOfTuples()) + " values for " + std::to_string(nf) + " polygons");
  for (vtkIdType f = 0; f < nf; ++f) {
    auto bare = [&] { return file + " polygon " + std::to_string(f); };
    m.first.push_back(labelValue(sources[0].first->GetComponent(f, sources[0].second), bare));
    if (sources.size() == 2) m.second.push_back(labelValue(sources[1].first->GetComponent(f, sources[1].second), bare));
    auto where = [&] { return faceWhere(m, static_cast<std::size_t>(f)); };
    vtkIdType n = 0;
    const vtkIdType* pts = nullptr;
    polys->GetCellAtId(f, n, pts);
    for (vtkIdType k = 0; k < n; ++k) {
      if (pts[k] < 0 || pts[k] >= np)
        throw InputError(where() + ": point index " + std::to_string(pts[k]) + " is out of range (the file has " +
                         std::to_string(np) + " points)");
      m.vertices.push_back(static_cast<Index>(pts[k]));
    }
    m.offsets.push_back(m.vertices.size());
    checkFaceLoop(m, static_cast<std::size_t>(f), where);
  }
  m.label_source = sources.size() == 1 ? "cell-data array '" + names[0] + "'"
                   : names.size() == 1 ? "the two components of cell-data array '" + names[0] + "'"
                                       : "cell-data arrays '" + names[0] + "', '" + names[1] + "'";
  return m;
}

// The mesh as a cell complex: each label a volume listing its faces.
ComplexFile toComplex(const LabelledFaces& m) {
  ComplexFile c;
  c.path = m.path;
  c.positions = m.positions;
  c.face_offsets = m.offsets;
  c.face_vertices = m.vertices;
  c.volume_noun = "cell";
  c.face_noun = m.face_noun;
  const bool two = !m.second.empty();
  // (label, face) pairs, sorted once: the volumes in label order.
  std::vector<std::pair<Label, Index>> pairs;
  pairs.reserve(m.numFaces() * (two ? 2 : 1));
  for (std::size_t f = 0; f < m.numFaces(); ++f) {
    if (!two) {
      pairs.emplace_back(m.first[f], static_cast<Index>(f));
      continue;
    }
    const Label a = m.first[f], b = m.second[f];
    if (a == b)
      throw InputError(faceWhere(m, f) + ": both sides carry label " + std::to_string(a) +
                       (a > 0 ? ": a face inside one cell" : ": no cell on either side (labels <= 0 are outside)"));
    if (a > 0) pairs.emplace_back(a, static_cast<Index>(f));
    if (b > 0) pairs.emplace_back(b, static_cast<Index>(f));
    if (a <= 0 && b <= 0)
      throw InputError(faceWhere(m, f) + ": no cell on either side (labels <= 0 are outside)");
  }
  std::sort(pairs.begin(), pairs.end());
  c.volume_offsets = {0};
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (i > 0 && pairs[i].first != pairs[i - 1].first) c.volume_offsets.push_back(c.volume_faces.size());
    if (i == 0 || pairs[i].first != pairs[i - 1].first) c.volume_label.push_back(pairs[i].first);
    c.volume_faces.push_back(pairs[i].second);
  }
  if (!pairs.empty()) c.volume_offsets.push_back(c.volume_faces.size());
  return c;
}

}  // namespace

bool isLabelledMesh(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".ply") return ext == ".obj" || ext == ".vtp";
  const PlyHeader h = readPlyHeader(path);
  const PlyElement* f = h.element("face");
  if (!h.element("vertex") || !f || !(f->property("vertex_indices") || f->property("vertex_index"))) return false;
  for (const char* n : kDefaultSingle)
    if (f->property(n)) return true;
  return f->property(kDefaultPair[0]) && f->property(kDefaultPair[1]);
}

ImportResult importLabelledMesh(const std::string& path, const ImportOptions& options) {
  detail::checkImportOptions(options);
  const std::string ext = lowerExtension(path);
  LabelledFaces faces;
  if (ext == ".ply") faces = readPly(path, options.label_array);
  else if (ext == ".obj") faces = readObj(path, options.label_array);
  else if (ext == ".vtp") faces = readVtp(path, options.label_array);
  else
    throw InputError("cannot import '" + path + "' as labelled_mesh: it reads .ply, .obj and .vtp files, not '" +
                     ext + "'");
  if (faces.numFaces() == 0) throw InputError("'" + path + "' has no faces: no cell to import");
  const ComplexFile m = toComplex(faces);
  ImportReport report;
  report.path = path;
  report.format = "labelled_mesh";
  report.file_vertices = faces.positions.size();
  report.file_faces = faces.numFaces();
  ImportResult result = detail::importComplex(m, options, std::move(report));
  if (!faces.second.empty() && result.tissue.dim() != 3)
    throw InputError("'" + path + "': its faces carry two labels (the cells on either side), but the cells are open "
                     "patches, not closed surfaces (cell label " + std::to_string(m.volume_label[0]) +
                     " is open): two labels per face describe the closed cells of a 3D tissue");
  result.report.notes.push_back(
      "cell properties: label (from the " + faces.label_source +
      (faces.second.empty() ? ")" : ", the cells on either side of each face; labels <= 0 are outside)"));
  return result;
}

}  // namespace tessella::io
