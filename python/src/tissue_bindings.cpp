// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// tessella.Tissue: counts, positions (copy or view), geometry queries,
// neighbourhood, lineage, editing. Elements are named by slot index (int);
// slots of removed elements are tombstones until compact() (generators and
// divisions make none, so slot == live element for most models).
#include <algorithm>
#include <optional>

#include "bindings.hpp"
#include "deferred_error.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

namespace tessella::python {

namespace {

template <typename H>
py::array_t<std::int64_t> indexArray(const LiveRange<H>& range) {
  std::vector<std::int64_t> ids;
  for (H h : range) ids.push_back(h.index());
  return py::array_t<std::int64_t>(static_cast<py::ssize_t>(ids.size()), ids.data());
}

template <typename H>
std::vector<std::int64_t> indexList(const std::vector<H>& handles) {
  std::vector<std::int64_t> out(handles.size());
  std::transform(handles.begin(), handles.end(), out.begin(), [](H h) { return std::int64_t(h.index()); });
  return out;
}

Embedding parseEmbedding(const std::string& name) {
  if (name == "planar") return Embedding::Planar;
  if (name == "surface") return Embedding::Surface;
  if (name == "volume") return Embedding::Volume;
  throw InputError("embedding: expected 'planar', 'surface' or 'volume', got '" + name + "'");
}

WallId checkedWall(const Tissue& t, long long index) {
  const std::size_t slots = t.slots(t.wallDegree());
  if (index < 0 || static_cast<std::size_t>(index) >= slots || !t.alive(WallId(static_cast<Index>(index))))
    throw InputError("wall " + std::to_string(index) + " is not a live wall (the tissue has " +
                     std::to_string(slots) + " wall slots)");
  return WallId(static_cast<Index>(index));
}

/// A Python index list as Index values; a negative or huge one is named like an out-of-range one.
std::vector<Index> indexListFrom(const std::vector<long long>& list, const std::string& what, std::size_t bound,
                                 const char* item, const char* items) {
  std::vector<Index> out(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i] < 0 || static_cast<unsigned long long>(list[i]) >= bound)
      throw InputError(what + ": " + item + " index " + std::to_string(list[i]) + " is out of range (there are " +
                       std::to_string(bound) + " " + items + ")");
    out[i] = static_cast<Index>(list[i]);
  }
  return out;
}

/// Tissue.from_polyhedra: checked (and oriented) in the caller's numbering, then built.
Tissue polyhedraFromArrays(const py::handle& positions_in, const std::vector<std::vector<long long>>& faces_in,
                           const std::vector<std::vector<long long>>& cells_in,
                           const std::optional<std::vector<std::vector<bool>>>& reversed) {
  const std::vector<Vec3> positions = vec3FromArray(positions_in, "from_polyhedra: positions");
  std::vector<std::vector<Index>> faces(faces_in.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    faces[f] = indexListFrom(faces_in[f], "face " + std::to_string(f), positions.size(), "vertex", "vertices");
  std::vector<std::vector<CellFace>> cells(cells_in.size());
  if (reversed && reversed->size() != cells_in.size())
    throw InputError("from_polyhedra: reversed has " + std::to_string(reversed->size()) + " lists for " +
                     std::to_string(cells_in.size()) + " cells");
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const std::vector<Index> list = indexListFrom(cells_in[k], "cell " + std::to_string(k), faces.size(), "face", "faces");
    if (reversed && (*reversed)[k].size() != list.size())
      throw InputError("from_polyhedra: reversed[" + std::to_string(k) + "] has " +
                       std::to_string((*reversed)[k].size()) + " flags for the " + std::to_string(list.size()) +
                       " faces of cell " + std::to_string(k));
    for (std::size_t i = 0; i < list.size(); ++i) cells[k].push_back({list[i], reversed && (*reversed)[k][i]});
  }
  checkPolyhedra(positions, faces, cells, reversed ? FaceOrientation::Given : FaceOrientation::Outward);
  return buildPolyhedralTissue(positions, faces, cells);
}

/// Per-cell-slot measures and centroids in one parallel sweep (dead slots hold zeros).
GeometryCache geometryOf(const Tissue& t) {
  GeometryCache cache;
  recomputeGeometry(t, cache, GeometryOptions{.edges = false, .second_moments = false});
  return cache;
}

}  // namespace

py::class_<Tissue> bindTissue(py::module_& m) {
  py::class_<Tissue> cls(m, "Tissue", R"doc(
A cell complex with vertex positions, property columns, lineage and a clock.

Elements are named by slot index (int). Cells are faces of a 2D tissue and
volumes of a 3D one; walls are edges (2D) or faces (3D). Arrays returned by
methods are indexed by slot; `cells()` lists the live ones.

Copies and views: positions() and property() return copies (always safe).
positions_view() and property_view() share the tissue's memory (no copy):
edits through them change the tissue, and they keep the Tissue object alive,
but any topological edit (split_cell, division, remove_cell, compact, adding
elements) may reallocate the storage and leaves an older view dangling:
fetch a new view after every edit. Growth (moving vertices) keeps views valid.
)doc");

  cls.def(py::init([](int dim, const std::string& embedding) {
            if (dim != 2 && dim != 3) throw InputError("dim: expected 2 or 3, got " + std::to_string(dim));
            return Tissue(dim, parseEmbedding(embedding));
          }),
          py::arg("dim") = 2, py::arg("embedding") = "planar",
          "An empty tissue; build a 2D one with add_vertex and add_polygon (a 3D one: Tissue.from_polyhedra).")
      .def_static("from_polyhedra", &polyhedraFromArrays, py::arg("positions"), py::arg("faces"), py::arg("cells"),
                  py::arg("reversed") = py::none(), R"doc(
A 3D tissue (embedding "volume") from arrays.

positions: (n, 3) vertex positions. faces: the walls, each a loop of vertex
indices; a wall between two cells is one face listed by both. cells: each a
list of face indices. reversed (optional): per cell, one flag per listed face,
True when that face's loop normal (right-hand rule) points into the cell;
without it the faces of every cell are oriented automatically, consistently
across their shared edges and pointing out of the cell.

InputError naming the cell, face, edge (by its two vertex indices) or vertex
for: an index out of range, a face with fewer than 3 vertices or a repeated
vertex, two faces with the same vertices, a face listed by more than two
cells or twice by one, a cell with fewer than 4 faces, an open cell (an edge
in one of its faces only), an edge in three or more of its faces, a cell in
separate pieces, a surface that cannot be (or, with reversed, is not)
consistently oriented, a cell whose given faces point inward, a cell that
encloses no volume.
)doc")
      .def("copy", [](const Tissue& t) { return Tissue(t); }, "A deep copy.")
      .def("__copy__", [](const Tissue& t) { return Tissue(t); })
      .def("__deepcopy__", [](const Tissue& t, py::dict) { return Tissue(t); }, py::arg("memo"))
      .def("__repr__",
           [](const Tissue& t) {
             return "<tessella.Tissue dim=" + std::to_string(t.dim()) + " embedding=" +
                    embeddingName(t.embedding()) + " cells=" + std::to_string(t.numCells()) +
                    " vertices=" + std::to_string(t.numVertices()) + " time=" + formatNumber(t.time()) +
                    ">";
           })
      // --- kind and counts
      .def_property_readonly("dim", &Tissue::dim)
      .def_property_readonly("embedding", [](const Tissue& t) { return std::string(embeddingName(t.embedding())); })
      .def_property_readonly("num_vertices", &Tissue::numVertices)
      .def_property_readonly("num_edges", &Tissue::numEdges)
      .def_property_readonly("num_faces", &Tissue::numFaces)
      .def_property_readonly("num_cells", &Tissue::numCells)
      .def_property_readonly("num_walls", &Tissue::numWalls)
      .def_property_readonly("cell_slots", &Tissue::cellSlots)
      .def_property_readonly("vertex_slots", [](const Tissue& t) { return t.slots(0); })
      .def("slots", &Tissue::slots, py::arg("degree"), "Slots (live and tombstones) of a degree 0..3.")
      .def("cells", [](const Tissue& t) { return indexArray(t.cells()); }, "Live cell indices (int64 array).")
      .def("walls", [](const Tissue& t) { return indexArray(t.walls()); }, "Live wall indices.")
      .def("vertices", [](const Tissue& t) { return indexArray(t.vertices()); }, "Live vertex indices.")
      .def_property("time", &Tissue::time, &Tissue::setTime, "The tissue clock.")
      .def_property_readonly("topology_version", &Tissue::topologyVersion)
      .def_property_readonly("geometry_version", &Tissue::geometryVersion)
      // --- positions
      .def("positions", [](const Tissue& t) { return vec3Copy(t.positions()); },
           "Vertex positions, (vertex_slots, 3) float64: a copy.")
      .def(
          "positions_view",
          [](py::object self, bool writable) {
            Tissue& t = self.cast<Tissue&>();
            if (writable) {
              const std::span<Vec3> p = t.mutablePositions();  // counts as a geometry change
              return vec3View(p.data(), p.size(), self, true);
            }
            const std::span<const Vec3> p = t.positions();
            return vec3View(const_cast<Vec3*>(p.data()), p.size(), self, false);
          },
          py::arg("writable") = true, R"doc(
Vertex positions as an (vertex_slots, 3) float64 array sharing the tissue's
memory (no copy). Writes move vertices. Valid until the next topological edit
(division, split, removal, compact, add_vertex); re-fetch after one. Writes
through the view after it was fetched are not seen by geometry caches keyed on
geometry_version: call mark_geometry_changed() after editing through an old view.
)doc")
      .def("set_positions",
           [](Tissue& t, py::handle values) {
             const std::vector<Vec3> v = vec3FromArray(values, "set_positions");
             if (v.size() != t.slots(0))
               throw InputError("set_positions: expected " + std::to_string(t.slots(0)) + " rows (vertex slots), got " +
                                std::to_string(v.size()));
             std::ranges::copy(v, t.mutablePositions().begin());
           },
           py::arg("positions"), "Replaces every vertex position (copies the (n, 3) array in).")
      .def("mark_geometry_changed", &Tissue::markGeometryChanged)
      .def("position", [](const Tissue& t, long long v) { return Vec3(t.position(checkedVertex(t, v))); }, py::arg("vertex"))
      .def("set_position", [](Tissue& t, long long v, const Vec3& p) { t.setPosition(checkedVertex(t, v), p); },
           py::arg("vertex"), py::arg("position"))
      // --- geometry
      .def("cell_measure", [](const Tissue& t, long long c) { return cellMeasure(t, checkedCell(t, c)); },
           py::arg("cell"), "Area (2D) or volume (3D) of a cell.")
      .def("cell_centroid", [](const Tissue& t, long long c) { return cellCentroid(t, checkedCell(t, c)); }, py::arg("cell"))
      .def("cell_principal_axes",
           [](const Tissue& t, long long c) {
             const PrincipalAxes a = cellPrincipalAxes(t, checkedCell(t, c));
             return py::make_tuple(a.values, a.axes);
           },
           py::arg("cell"), "(values, axes): second moments by decreasing extent; axes[:, 0] is the main axis.")
      .def("cell_measures",
           [](const Tissue& t) {
             const GeometryCache g = geometryOf(t);
             const auto& v = t.dim() == 2 ? g.face_area : g.volume;
             return py::array_t<double>(static_cast<py::ssize_t>(t.cellSlots()), v.data());
           },
           "Area/volume of every cell slot (float64 array, a copy; zeros for dead slots).")
      .def("cell_centroids",
           [](const Tissue& t) {
             const GeometryCache g = geometryOf(t);
             const auto& v = t.dim() == 2 ? g.face_centroid : g.volume_centroid;
             return vec3Copy(std::span<const Vec3>(v.data(), t.cellSlots()));
           },
           "Centroid of every cell slot, (cell_slots, 3) float64 (a copy).")
      .def("total_measure", [](const Tissue& t) { return totalMeasure(t); }, "Total area (2D) or volume (3D).")
      .def("wall_measure", [](const Tissue& t, long long w) { return wallMeasure(t, checkedWall(t, w)); }, py::arg("wall"))
      // --- neighbourhood
      .def("cell_neighbors", [](const Tissue& t, long long c) { return indexList(t.cellNeighbors(checkedCell(t, c))); },
           py::arg("cell"), "Cells sharing a wall with the cell.")
      .def("cell_walls", [](const Tissue& t, long long c) { return indexList(t.cellWalls(checkedCell(t, c))); }, py::arg("cell"))
      .def("cell_vertices", [](const Tissue& t, long long c) { return indexList(t.cellVertices(checkedCell(t, c))); },
           py::arg("cell"))
      .def("wall_cells", [](const Tissue& t, long long w) { return indexList(t.wallCells(checkedWall(t, w))); }, py::arg("wall"))
      .def("is_boundary_wall", [](const Tissue& t, long long w) { return t.isBoundaryWall(checkedWall(t, w)); }, py::arg("wall"))
      // --- lineage
      .def("lineage_id", [](const Tissue& t, long long c) { return t.lineageId(checkedCell(t, c)); }, py::arg("cell"),
           "Unique over the tissue's history, never reused: track cells by it, not by index.")
      .def("parent_id", [](const Tissue& t, long long c) { return t.parentId(checkedCell(t, c)); }, py::arg("cell"),
           "Lineage id of the mother, -1 for a founder.")
      .def("birth_time", [](const Tissue& t, long long c) { return t.birthTime(checkedCell(t, c)); }, py::arg("cell"))
      // --- building and editing
      .def("add_vertex", [](Tissue& t, const Vec3& p) { return t.addVertex(p).index(); }, py::arg("position"))
      .def("add_polygon",
           [](Tissue& t, const std::vector<long long>& loop) {
             // A face of a 3D tissue bounds no cell until a volume lists it, and Python cannot add volumes.
             if (t.dim() == 3)
               throw InputError("add_polygon builds the cells of a 2D tissue; a 3D tissue's faces are walls of "
                                "its polyhedral cells: build it whole with Tissue.from_polyhedra(positions, faces, "
                                "cells)");
             std::vector<VertexId> ids;
             for (long long v : loop) ids.push_back(checkedVertex(t, v));
             return t.addPolygon(std::span<const VertexId>(ids)).index();
           },
           py::arg("loop"),
           "A cell of a 2D tissue from a vertex loop, counter-clockwise seen from +z. InputError for a 3D tissue "
           "(use Tissue.from_polyhedra).")
      .def("split_cell",
           [](Tissue& t, long long c, const Vec3& point, const Vec3& normal, double snap, double min_fraction) {
             const CellSplit s = t.splitCell(checkedCell(t, c), Plane{point, normal},
                                             SplitOptions{.snap_tolerance = snap, .min_fraction = min_fraction});
             raiseDeferredError();  // a custom property division failed (the split is done)
             py::dict d;
             d["daughter"] = s.daughter.index();
             d["wall"] = s.wall.index();
             d["new_vertices"] = indexList(s.new_vertices);
             return d;
           },
           py::arg("cell"), py::arg("point"), py::arg("normal"), py::arg("snap_tolerance") = 1e-9,
           py::arg("min_fraction") = 1e-6,
           "Divides a cell by a plane; the mother keeps its index (negative side), the daughter is new. "
           "Property columns divide by their policy. GeometryError (tissue unchanged) for a bad plane.")
      .def("remove_cell", [](Tissue& t, long long c) { t.removeCell(checkedCell(t, c)); }, py::arg("cell"))
      .def("compact",
           [](Tissue& t) {
             const Renumbering r = t.compact();
             py::list maps;
             for (const auto& v : r.old_to_new) {
               std::vector<std::int64_t> map(v.size());
               for (std::size_t i = 0; i < v.size(); ++i) map[i] = v[i] == kInvalidIndex ? -1 : std::int64_t(v[i]);
               maps.append(py::array_t<std::int64_t>(static_cast<py::ssize_t>(map.size()), map.data()));
             }
             return maps;
           },
           "Drops tombstones; returns old-to-new index arrays per degree 0..3 (-1: removed).")
      .def("validate",
           [](const Tissue& t, bool euler) {
             const ValidationReport r = validate(t, ValidateOptions{.check_euler = euler});
             return py::make_tuple(r.ok, r.message);
           },
           py::arg("check_euler") = true, "(ok, message): the first violated invariant, naming the element.")
      .def("validate_or_throw", [](const Tissue& t, bool euler) { validateOrThrow(t, ValidateOptions{.check_euler = euler}); },
           py::arg("check_euler") = true, "Raises TopologyError with the first violated invariant.");
  return cls;
}

}  // namespace tessella::python
