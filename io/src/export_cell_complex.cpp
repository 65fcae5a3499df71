// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Cell-complex PLY export (tessella/io/cell_complex_ply.hpp).

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <set>
#include <typeindex>
#include <typeinfo>

#include "tessella/io/cell_complex_ply.hpp"
#include "tessella/io/text_file.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::io {

namespace {

// Appends values as ASCII tokens or little-endian binary.
class PlyWriter {
 public:
  explicit PlyWriter(bool binary) : binary_(binary) {}
  void real(double v) {
    if (!binary_) return token(formatNumber(v));  // shortest exact text
    bytes(v);
  }
  void integer(std::int64_t v) {
    if (!binary_) return token(std::to_string(v));
    bytes(static_cast<std::int32_t>(v));
  }
  void endElement() {
    if (!binary_) out_ += '\n';
  }
  std::string& text() { return out_; }

 private:
  void token(const std::string& t) {
    if (!out_.empty() && out_.back() != '\n') out_ += ' ';
    out_ += t;
  }
  template <typename T>
  void bytes(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if constexpr (std::endian::native == std::endian::big)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    out_.append(b, sizeof(T));
  }
  bool binary_;
  std::string out_;
};

// The `label` cell property when every live cell has its own, else the lineage ids.
std::vector<std::int64_t> volumeLabels(const Tissue& t, std::string& source) {
  std::vector<std::int64_t> labels;
  const PropertyStore& props = t.cellProperties();
  bool unique = false;
  const PropertyColumnBase* found = props.find("label");
  if (found && found->type() == typeid(std::int64_t)) {
    const auto& column = props.get<std::int64_t>("label");
    std::set<std::int64_t> seen;
    unique = true;
    for (CellId c : t.cells()) {
      labels.push_back(column[c]);
      unique = unique && seen.insert(column[c]).second;
    }
  }
  if (unique) {
    source = "label";
    return labels;
  }
  labels.clear();
  for (CellId c : t.cells()) labels.push_back(t.lineageId(c));
  source = "lineage_id";
  return labels;
}

}  // namespace

CellComplexPlyInfo writeCellComplexPly(const Tissue& t, const std::string& path,
                                       const CellComplexPlyOptions& options) {
  CellComplexPlyInfo info;
  const std::vector<std::int64_t> labels = volumeLabels(t, info.label_source);
  {
    std::size_t k = 0;
    for (CellId c : t.cells()) {
      const std::int64_t l = labels[k++];
      if (l < std::numeric_limits<std::int32_t>::min() || l > std::numeric_limits<std::int32_t>::max())
        throw InputError("cannot write '" + path + "': cell " + std::to_string(c.index()) + " has " +
                         info.label_source + " " + std::to_string(l) +
                         ", beyond the 32-bit int of the file's volume labels");
    }
  }
  // Live elements, numbered densely in index order.
  std::vector<Index> vertex_number(t.slots(0), kInvalidIndex), face_number(t.slots(2), kInvalidIndex);
  for (VertexId v : t.vertices()) vertex_number[v.index()] = static_cast<Index>(info.vertices++);
  for (EdgeId e : t.edges()) (void)e, ++info.edges;
  std::vector<FaceId> faces;
  for (FaceId f : t.faces()) {
    face_number[f.index()] = static_cast<Index>(faces.size());
    faces.push_back(f);
  }
  info.faces = faces.size();
  info.volumes = t.numCells();
  const CellComplex& cx = t.topology();

  PlyWriter w(options.binary);
  std::string& out = w.text();
  out = "ply\nformat " + std::string(options.binary ? "binary_little_endian" : "ascii") + " 1.0\n";
  out += "comment cell complex written by Tessella (" + std::string(embeddingName(t.embedding())) + ", dim " +
         std::to_string(t.dim()) + "); volume face_index is 0-based; label from " + info.label_source + "\n";
  out += "element vertex " + std::to_string(info.vertices) +
         "\nproperty double x\nproperty double y\nproperty double z\n";
  out += "element face " + std::to_string(info.faces) + "\nproperty list int int vertex_index\n";
  out += "element edge " + std::to_string(info.edges) + "\nproperty int source\nproperty int target\n";
  out += "element volume " + std::to_string(info.volumes) + "\nproperty list int int face_index\nproperty int label\n";
  out += "end_header\n";
  for (VertexId v : t.vertices()) {
    const Vec3& p = t.position(v);
    w.real(p.x()), w.real(p.y()), w.real(p.z());
    w.endElement();
  }
  for (FaceId f : faces) {
    const auto loop = cx.faceVertices(f);
    w.integer(static_cast<std::int64_t>(loop.size()));
    for (VertexId v : loop) w.integer(vertex_number[v.index()]);
    w.endElement();
  }
  for (EdgeId e : t.edges()) {
    w.integer(vertex_number[cx.edgeFrom(e).index()]);
    w.integer(vertex_number[cx.edgeTo(e).index()]);
    w.endElement();
  }
  std::size_t k = 0;
  for (CellId c : t.cells()) {
    if (t.dim() == 3) {
      const auto walls = cx.volumeFaces(t.cellVolume(c));
      w.integer(static_cast<std::int64_t>(walls.size()));
      for (const OrientedFace& of : walls) w.integer(face_number[of.handle().index()]);
    } else {
      w.integer(1);
      w.integer(face_number[t.cellFace(c).index()]);
    }
    w.integer(labels[k++]);
    w.endElement();
  }
  writeTextFile(path, out);
  return info;
}

}  // namespace tessella::io
