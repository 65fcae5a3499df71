// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/network_graph.hpp"

#include <cmath>
#include <typeindex>
#include <unordered_map>

#include "tessella/tissue/errors.hpp"

namespace tessella::networks {

void NetworkGraph::validate() const {
  const auto n = static_cast<int>(measure.size());
  if (centroid.size() != measure.size())
    throw InputError("network graph: " + std::to_string(centroid.size()) + " centroids for " + std::to_string(n) +
                     " cells");
  for (int c = 0; c < n; ++c)
    if (!(std::isfinite(measure[c]) && measure[c] > 0.0))
      throw InputError("network graph: cell " + std::to_string(c) + " has measure " + std::to_string(measure[c]) +
                       "; it must be > 0");
  for (std::size_t k = 0; k < interfaces.size(); ++k) {
    const NetworkInterface& f = interfaces[k];
    if (f.cell_i < 0 || f.cell_j < 0 || f.cell_i >= n || f.cell_j >= n || f.cell_i == f.cell_j)
      throw InputError("network graph: interface " + std::to_string(k) + " joins cells " + std::to_string(f.cell_i) +
                       " and " + std::to_string(f.cell_j) + "; they must be distinct and in [0, " +
                       std::to_string(n) + ")");
    if (!(std::isfinite(f.measure) && f.measure >= 0.0))
      throw InputError("network graph: interface " + std::to_string(k) + " has measure " +
                       std::to_string(f.measure) + "; it must be >= 0");
  }
  for (const auto& [name, values] : properties)
    if (values.size() != measure.size())
      throw InputError("network graph: property '" + name + "' has " + std::to_string(values.size()) +
                       " values for " + std::to_string(n) + " cells");
}

namespace {
// Unit normal of wall w pointing away from the cell whose centroid is `from`.
Vec3 wallNormal(const Tissue& t, const GeometryCache& g, WallId w, const Vec3& from) {
  if (t.dim() == 3) {
    Vec3 n = g.face_normal[w.index()];
    if (n.dot(g.face_centroid[w.index()] - from) < 0) n = -n;
    return n;
  }
  // 2D (planar or surface): the direction in the plane of the edge and the
  // cell centroid that is perpendicular to the edge, pointing away from the cell.
  const auto v = t.topology().edgeVertices(EdgeId(w.index()));
  const Vec3& a = t.position(v[0]);
  const Vec3& b = t.position(v[1]);
  Vec3 e = b - a;
  const double len = e.norm();
  if (!(len > 0)) return Vec3::Zero();
  e /= len;
  Vec3 d = 0.5 * (a + b) - from;
  d -= d.dot(e) * e;
  const double dn = d.norm();
  return dn > 0 ? Vec3(d / dn) : Vec3::Zero();
}
}  // namespace

bool onPositiveSide(const Tissue& tissue, WallId wall, CellId cell) {
  const CellComplex& t = tissue.topology();
  if (tissue.dim() == 2) {
    for (OrientedEdge e : t.faceEdges(FaceId(cell.index())))
      if (e.handle().index() == wall.index()) return !e.reversed();
  } else {
    for (OrientedFace f : t.volumeFaces(VolumeId(cell.index())))
      if (f.handle().index() == wall.index()) return !f.reversed();
  }
  throw InputError("network: wall " + std::to_string(wall.index()) + " does not bound cell " +
                   std::to_string(cell.index()));
}

NetworkGraph networkGraph(const Tissue& tissue, GeometryCache& geometry, const std::vector<std::string>& properties,
                          std::vector<CellId>* cells_out, std::vector<std::vector<InterfaceWall>>* walls_out) {
  if (walls_out) walls_out->clear();
  geometry.require(tissue, tissue.dim() == 2 ? kCellMeasures | GeometryQuantity::EdgeLengths : kCellMeasures);
  NetworkGraph g;
  std::vector<int> index(tissue.cellSlots(), -1);
  std::vector<CellId> cells;
  for (CellId c : tissue.cells()) {
    index[c.index()] = static_cast<int>(cells.size());
    cells.push_back(c);
    g.measure.push_back(geometry.cellMeasure(tissue, c));
    g.centroid.push_back(geometry.cellCentroid(tissue, c));
  }
  // One interface per neighbouring pair, in the order the pairs are met.
  std::unordered_map<std::uint64_t, std::size_t> pair_index;
  for (WallId w : tissue.walls()) {
    const std::vector<CellId> two = tissue.wallCells(w);
    if (two.size() != 2) continue;
    int i = index[two[0].index()], j = index[two[1].index()];
    CellId cell_i = two[0];
    if (i > j) {
      std::swap(i, j);
      cell_i = two[1];
    }
    const double m = tissue.dim() == 2 ? geometry.edge_length[w.index()] : geometry.face_area[w.index()];
    const Vec3 n = wallNormal(tissue, geometry, w, g.centroid[static_cast<std::size_t>(i)]);
    const std::uint64_t key = (static_cast<std::uint64_t>(i) << 32) | static_cast<std::uint32_t>(j);
    auto [it, fresh] = pair_index.emplace(key, g.interfaces.size());
    if (fresh) g.interfaces.push_back({i, j, 0.0, Vec3::Zero()});
    if (walls_out) {
      if (fresh) walls_out->emplace_back();
      (*walls_out)[it->second].push_back({w, m, onPositiveSide(tissue, w, cell_i)});
    }
    NetworkInterface& f = g.interfaces[it->second];
    f.measure += m;
    f.normal += m * n;
  }
  for (NetworkInterface& f : g.interfaces) {
    const double len = f.normal.norm();
    if (len > 0) f.normal /= len;
  }
  for (const std::string& name : properties) {
    const PropertyColumnBase* column = tissue.cellProperties().find(name);
    if (!column) throw InputError("network: the cell property '" + name + "' is not on the tissue");
    std::vector<double>& out = g.properties[name];
    if (column->type() == std::type_index(typeid(double))) {
      const auto& values = tissue.cellProperties().get<double>(name);
      for (CellId c : cells) out.push_back(values[c]);
    } else if (column->type() == std::type_index(typeid(int))) {
      // An int property (a label, e.g. the primordium id) is read as its value.
      const auto& values = tissue.cellProperties().get<int>(name);
      for (CellId c : cells) out.push_back(static_cast<double>(values[c]));
    } else {
      throw InputError("network: the cell property '" + name + "' does not hold numbers (double or int)");
    }
  }
  if (cells_out) *cells_out = std::move(cells);
  return g;
}

}  // namespace tessella::networks
