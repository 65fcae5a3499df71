// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/tissue_membranes.hpp"

#include "tessella/mechanics/errors.hpp"
#include "tessella/mechanics/membrane_triangulation.hpp"
#include "tessella/mechanics/rigid_motions.hpp"
#include "tessella/mechanics/wall_state.hpp"
#include "tessella/mechanics/wall_stress.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

namespace tessella::mechanics {
namespace {

std::vector<Index> faceLoop(const Tissue& tissue, FaceId f) {
  std::vector<Index> loop;
  for (VertexId v : tissue.topology().faceVertices(f)) loop.push_back(v.index());
  return loop;
}

// Signed volume of the cone from `origin` to the fan of `loop`.
double coneVolume(const Tissue& tissue, const std::vector<Index>& loop, const Vec3& origin) {
  Vec3 apex = Vec3::Zero();
  for (Index v : loop) apex += tissue.positions()[v];
  apex /= static_cast<double>(loop.size());
  double v = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 a = tissue.positions()[loop[i]] - origin, b = tissue.positions()[loop[(i + 1) % loop.size()]] - origin;
    v += (apex - origin).dot(a.cross(b));
  }
  return v / 6.0;
}

std::string faceName(const Tissue& tissue, FaceId f) {
  if (tissue.dim() == 2) return "cell " + std::to_string(f.index()) + " (lineage " +
                                 std::to_string(tissue.lineageId(CellId(f.index()))) + ")";
  return "wall " + std::to_string(f.index());
}

// The open rims of a sheet, each as the loop that closes it: its boundary
// edges traversed against their cell's loop, so that sheet and lids form a
// consistently oriented closed surface. Loops start at their smallest vertex slot.
std::vector<std::vector<Index>> rimLoops(const Tissue& tissue) {
  std::vector<Index> next(tissue.slots(0), kInvalidIndex);
  for (WallId w : tissue.walls()) {
    if (!tissue.isBoundaryWall(w)) continue;
    const auto uv = tissue.topology().edgeVertices(EdgeId(w.index()));
    const auto loop = tissue.topology().faceVertices(tissue.cellFace(tissue.wallCells(w).front()));
    bool forward = false;  // the cell's loop runs u -> v
    for (std::size_t i = 0; i < loop.size(); ++i)
      if (loop[i] == uv[0] && loop[(i + 1) % loop.size()] == uv[1]) forward = true;
    if (forward)
      next[uv[1].index()] = uv[0].index();
    else
      next[uv[0].index()] = uv[1].index();
  }
  std::vector<std::vector<Index>> loops;
  std::vector<std::uint8_t> used(next.size(), 0);
  for (Index start = 0; start < next.size(); ++start) {
    if (next[start] == kInvalidIndex || used[start]) continue;
    std::vector<Index> loop;
    for (Index v = start; v != kInvalidIndex && !used[v]; v = next[v]) {
      used[v] = 1;
      loop.push_back(v);
    }
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

// +1 when the sheet and its lids enclose a positive volume, else -1.
double sheetSign(const Tissue& tissue, const std::vector<FaceId>& faces, const Vec3& origin) {
  double total = 0.0;
  for (FaceId f : faces) total += coneVolume(tissue, faceLoop(tissue, f), origin);
  for (const auto& lid : rimLoops(tissue)) total += coneVolume(tissue, lid, origin);
  return total < 0.0 ? -1.0 : 1.0;
}

double restArea(const RestMetric& c) { return 0.5 * std::sqrt(std::max(c(0) * c(2) - c(1) * c(1), 0.0)); }

}  // namespace

Vec3 FibreRule::at(const Vec3& c) const {
  switch (kind) {
    case Kind::None: return Vec3::Zero();
    case Kind::Fixed: return vector;
    case Kind::Circumferential: return vector.cross(c - point);
  }
  return Vec3::Zero();
}

void MembraneGrowthParams::check() const {
  material.check();
  growth.check();
  if (!std::isfinite(pressure)) throw InputError("mechanics: pressure " + formatNumber(pressure) + " must be finite");
  if (!(base_distance >= 0.0 && std::isfinite(base_distance)))
    throw InputError("mechanics: base_distance " + formatNumber(base_distance) + " must be >= 0");
  if (base_height && !std::isfinite(*base_height))
    throw InputError("mechanics: base height " + formatNumber(*base_height) + " must be finite");
  if (!(plane_distance >= 0.0 && std::isfinite(plane_distance)))
    throw InputError("mechanics: plane_distance " + formatNumber(plane_distance) + " must be >= 0");
  for (const SymmetryPlane& q : planes)
    if (q.axis < 0 || q.axis > 2 || !std::isfinite(q.offset))
      throw InputError("mechanics: symmetry plane axis " + std::to_string(q.axis) + " offset " +
                       formatNumber(q.offset) + ": the axis is 0, 1 or 2 (x, y, z) and the offset finite");
  if (support == Support::Symmetry && planes.empty())
    throw InputError("mechanics: the symmetry support holds the tissue by its symmetry planes; none given");
  if (point && !point->allFinite())
    throw InputError("mechanics: support point " + formatPoint(*point) + " must be finite");
  feedback.check();
  if (fibres.kind != FibreRule::Kind::None && !(fibres.vector.norm() > 0.0))
    throw InputError("mechanics: the fibre direction (or axis) must not be zero");
}

const EnumTable<MembraneGrowthParams::Support>& membraneSupports() {
  static const EnumTable<MembraneGrowthParams::Support> table(
      "membrane support",
      {{"base", MembraneGrowthParams::Support::Base,
        "the vertices within base_distance above the base plane (a dome's or cylinder's base ring, a 3D "
        "tissue's bottom)"},
       {"boundary", MembraneGrowthParams::Support::Boundary,
        "every vertex on a sheet's boundary walls (the rim of a cropped patch; sheets only)"},
       {"point", MembraneGrowthParams::Support::Point,
        "a closed body held at one point: the vertex nearest support_point fixed, two components of the vertex "
        "farthest from it and one of the vertex farthest from their line, only those that remove a rigid motion "
        "the symmetry planes leave (3 + 2 + 1 alone: no work against turgor, no constraint on the deformation)"},
       {"symmetry", MembraneGrowthParams::Support::Symmetry,
        "the symmetry planes alone (symmetry_planes; three for an eighth of a closed body)"}});
  return table;
}

std::string SymmetryPlane::text() const { return std::string(1, "xyz"[axis]) + " = " + formatNumber(offset); }

std::vector<SymmetryPlane> parseSymmetryPlanes(const std::string& text, const std::string& source) {
  std::vector<SymmetryPlane> planes;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    std::string item = text.substr(start, end - start);
    item.erase(std::remove_if(item.begin(), item.end(), [](unsigned char c) { return std::isspace(c); }), item.end());
    start = end + 1;
    if (item.empty()) {
      if (end < text.size() || !planes.empty() || text.find_first_not_of(" \t") != std::string::npos)
        throw InputError(source + ": '" + text + "' has an empty plane (write for example \"x = 0, y = 0\")");
      break;
    }
    SymmetryPlane q;
    const std::size_t axis = std::string("xyz").find(static_cast<char>(std::tolower(item[0])));
    double offset = 0.0;
    const char* first = item.data() + 2;
    const char* last = item.data() + item.size();
    const bool ok = item.size() > 2 && axis != std::string::npos && item[1] == '=' &&
                    [&] {
                      const auto r = std::from_chars(first, last, offset);
                      return r.ec == std::errc() && r.ptr == last && std::isfinite(offset);
                    }();
    if (!ok)
      throw InputError(source + ": plane '" + item + "' is not x = c, y = c or z = c (c a finite number)");
    q.axis = static_cast<int>(axis);
    q.offset = offset;
    for (const SymmetryPlane& p : planes)
      if (p.axis == q.axis && p.offset == q.offset) throw InputError(source + ": plane '" + item + "' is given twice");
    planes.push_back(q);
  }
  return planes;
}

std::vector<FaceId> membraneFaces(const Tissue& tissue) {
  std::vector<FaceId> faces;
  if (tissue.dim() == 2) {
    if (tissue.embedding() != Embedding::Surface)
      throw MechanicsError("mechanics: membranes need a curved sheet (embedding surface) or a 3D tissue; this "
                           "tissue is planar (use the wall_springs model)");
    for (CellId c : tissue.cells()) faces.push_back(tissue.cellFace(c));
  } else {
    for (FaceId f : tissue.faces()) faces.push_back(f);
  }
  return faces;
}

Eigen::VectorXd spatialDofs(const Tissue& tissue) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(tissue.slots(0)));
  const auto p = tissue.positions();
  for (std::size_t i = 0; i < p.size(); ++i) x.segment<3>(3 * static_cast<Eigen::Index>(i)) = p[i];
  return x;
}

void setSpatialDofs(Tissue& tissue, const Eigen::VectorXd& x) {
  auto p = tissue.mutablePositions();
  for (VertexId v : tissue.vertices()) p[v.index()] = x.segment<3>(3 * static_cast<Eigen::Index>(v.index()));
}

Vec3 sheetOrigin(const Tissue& tissue) {
  Vec3 mean = Vec3::Zero();
  double zmin = std::numeric_limits<double>::infinity();
  for (VertexId v : tissue.vertices()) {
    mean += tissue.position(v);
    zmin = std::min(zmin, tissue.position(v).z());
  }
  mean /= static_cast<double>(std::max<std::size_t>(tissue.numVertices(), 1));
  return {mean.x(), mean.y(), zmin};
}

std::vector<double> facePressures(const Tissue& tissue, const std::vector<FaceId>& faces,
                                  const std::vector<double>& cell_pressure, const Vec3& origin) {
  std::vector<double> p(faces.size(), 0.0);
  if (tissue.dim() == 2) {
    const double sign = sheetSign(tissue, faces, origin);
    for (std::size_t i = 0; i < faces.size(); ++i) p[i] = sign * cell_pressure[faces[i].index()];
    return p;
  }
  std::vector<std::size_t> position(tissue.slots(2), 0);
  for (std::size_t i = 0; i < faces.size(); ++i) position[faces[i].index()] = i;
  for (CellId c : tissue.cells())
    for (const OrientedFace& o : tissue.topology().volumeFaces(tissue.cellVolume(c)))
      p[position[o.handle().index()]] += cell_pressure[c.index()] * (o.reversed() ? -1.0 : 1.0);
  return p;
}

Vec3 membraneOrigin(const Tissue& tissue, const MembraneGrowthParams& params) {
  if (tissue.dim() != 2) return Vec3::Zero();
  Vec3 origin = sheetOrigin(tissue);
  for (const SymmetryPlane& q : params.planes) {
    for (const SymmetryPlane& p : params.planes)
      if (p.axis == q.axis && p.offset != q.offset)
        throw MechanicsError("mechanics: symmetry planes " + p.text() + " and " + q.text() +
                             " are parallel: a sheet's cone origin must lie on every plane (its rims along them "
                             "are closed there); give one plane per axis");
    origin[q.axis] = q.offset;
  }
  return origin;
}

namespace {

// Per vertex slot, bit k set when the vertex lies within plane_distance of params.planes[k].
std::vector<std::uint32_t> planeMembership(const Tissue& tissue, const MembraneGrowthParams& params) {
  std::vector<std::uint32_t> on(tissue.slots(0), 0);
  for (std::size_t k = 0; k < params.planes.size() && k < 32; ++k)
    for (VertexId v : tissue.vertices())
      if (std::abs(tissue.position(v)[params.planes[k].axis] - params.planes[k].offset) <= params.plane_distance)
        on[v.index()] |= std::uint32_t{1} << k;
  return on;
}

// The vertices the base or boundary support holds (per vertex slot).
std::vector<std::uint8_t> heldVertices(const Tissue& tissue, const MembraneGrowthParams& params) {
  std::vector<std::uint8_t> fixed(tissue.slots(0), 0);
  if (params.support == MembraneGrowthParams::Support::Point ||
      params.support == MembraneGrowthParams::Support::Symmetry)
    return fixed;
  if (params.support == MembraneGrowthParams::Support::Boundary) {
    if (tissue.dim() != 2)
      throw MechanicsError("mechanics: the boundary support holds a sheet's rims; a 3D tissue has none (use the "
                           "base support)");
    bool any = false;
    for (WallId w : tissue.walls()) {
      if (!tissue.isBoundaryWall(w)) continue;
      for (VertexId v : tissue.topology().edgeVertices(EdgeId(w.index()))) fixed[v.index()] = 1;
      any = true;
    }
    if (!any)
      throw MechanicsError("mechanics: the boundary support fixes nothing: this sheet is closed (no boundary "
                           "walls; use the base support)");
    return fixed;
  }
  double zmin = std::numeric_limits<double>::infinity();
  for (VertexId v : tissue.vertices()) zmin = std::min(zmin, tissue.position(v).z());
  if (params.base_height) zmin = *params.base_height;
  for (VertexId v : tissue.vertices()) fixed[v.index()] = tissue.position(v).z() <= zmin + params.base_distance;
  return fixed;
}

}  // namespace

std::vector<std::uint8_t> membraneFixedDofs(const Tissue& tissue, const MembraneGrowthParams& params) {
  if (params.planes.size() > 32) throw MechanicsError("mechanics: more than 32 symmetry planes");
  std::vector<std::uint8_t> fixed(3 * tissue.slots(0), 1);
  const std::vector<std::uint8_t> held = heldVertices(tissue, params);
  const std::vector<std::uint32_t> on = planeMembership(tissue, params);
  for (VertexId v : tissue.vertices())
    for (int k = 0; k < 3; ++k) fixed[3 * v.index() + static_cast<std::size_t>(k)] = held[v.index()];
  for (std::size_t k = 0; k < params.planes.size(); ++k)
    for (VertexId v : tissue.vertices())
      if (on[v.index()] >> k & 1u) fixed[3 * v.index() + static_cast<std::size_t>(params.planes[k].axis)] = 1;
  if (params.support == MembraneGrowthParams::Support::Point) {
    Vec3 point = Vec3::Zero();
    if (params.point) {
      point = *params.point;
    } else {
      for (VertexId v : tissue.vertices()) point += tissue.position(v);
      point /= static_cast<double>(std::max<std::size_t>(tissue.numVertices(), 1));
    }
    fixPointSupport(tissue, point, fixed);
  }
  return fixed;
}

std::vector<std::uint8_t> membraneSupport(const Tissue& tissue, const MembraneGrowthParams& params) {
  const std::vector<std::uint8_t> dofs = membraneFixedDofs(tissue, params);
  std::vector<std::uint8_t> fixed(tissue.slots(0), 0);
  for (VertexId v : tissue.vertices()) {
    const std::size_t i = 3 * static_cast<std::size_t>(v.index());
    fixed[v.index()] = dofs[i] && dofs[i + 1] && dofs[i + 2];
  }
  return fixed;
}

FanMembraneModel buildTissueMembranes(Tissue& tissue, const MembraneGrowthParams& params, MembraneRestState& state,
                                      std::size_t* reset) {
  const std::vector<FaceId> faces = membraneFaces(tissue);
  const Eigen::VectorXd x = spatialDofs(tissue);
  PropertyStore& face_props = tissue.properties(2);
  if (!face_props.has(kMembraneRestRatioName))
    face_props.add<double>(kMembraneRestRatioName, 1.0, DivisionPolicy::Copy);
  const auto& ratio = face_props.get<double>(kMembraneRestRatioName);
  const auto& pressure = cellOutput(tissue, kTurgorPressureName, params.pressure);
  const PropertyColumn<double>* young =
      tissue.cellProperties().has(kYoungScaleName) ? &tissue.cellProperties().get<double>(kYoungScaleName) : nullptr;
  // A sheet's cells are its faces: one store serves both (cells of a sheet, walls of a 3D tissue).
  const PropertyColumn<double>* fibre_ratio =
      face_props.has(kFibreRatioName) ? &face_props.get<double>(kFibreRatioName) : nullptr;
  const Vec3 origin = membraneOrigin(tissue, params);
  const std::vector<double> p = facePressures(tissue, faces, pressure.values(), origin);
  state.loops.resize(tissue.slots(2));
  state.rest.resize(tissue.slots(2));
  state.triangulations.resize(tissue.slots(2));
  state.fibres.resize(tissue.slots(2), Vec3::Zero());
  const bool feedback = params.feedback.rate > 0.0 || params.feedback.noise > 0.0;
  std::size_t resets = 0;
  std::vector<MembranePolygon> polygons(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const FaceId f = faces[i];
    MembranePolygon& poly = polygons[i];
    poly.loop = faceLoop(tissue, f);
    std::vector<Vec3> positions;
    for (Index v : poly.loop) positions.push_back(tissue.positions()[v]);
    const std::size_t slot = f.index();
    if (state.loops[slot] != poly.loop ||
        state.rest[slot].size() != state.triangulations[slot].size(poly.loop.size())) {
      // A new reference: the triangulation is chosen in the current shape and kept while the loop lives.
      try {
        state.triangulations[slot] = membraneTriangulation(positions);
      } catch (const Error& e) {
        throw MechanicsError("mechanics: " + faceName(tissue, f) + ": " + e.what());
      }
      state.loops[slot] = poly.loop;
      state.rest[slot] = FanMembraneModel::currentMetrics(x, poly.loop, state.triangulations[slot]);
      for (RestMetric& m : state.rest[slot]) m *= ratio[f];
      ++resets;
    }
    poly.triangulation = state.triangulations[slot];
    poly.rest = state.rest[slot];
    Vec3 mean = Vec3::Zero();
    for (const Vec3& q : positions) mean += q;
    poly.fibre = params.fibres.at(mean / static_cast<double>(positions.size()));
    if (feedback) {  // the polygon's own fibre, kept through divisions (both parts keep the slot's or copy it)
      if (state.fibres[slot].norm() > 0.0) poly.fibre = state.fibres[slot];
      state.fibres[slot] = poly.fibre;
    }
    poly.pressure = p[i];
    if (fibre_ratio) {
      const double r = (*fibre_ratio)[f];
      MembraneMaterial own = params.material;
      own.fibre_ratio = r;
      try {
        own.check();
      } catch (const InputError& e) {
        throw MechanicsError("mechanics: " + faceName(tissue, f) + ": property " + kFibreRatioName + " " +
                             formatNumber(r) + ": " + e.what());
      }
      poly.fibre_ratio = r;
    }
    if (young) {
      if (tissue.dim() == 2) {
        poly.young_scale = (*young)[CellId(slot)];
      } else {
        const auto cells = tissue.wallCells(WallId(slot));
        double s = 0.0;
        for (CellId c : cells) s += (*young)[c];
        poly.young_scale = s / static_cast<double>(cells.size());
      }
    }
  }
  if (tissue.dim() == 2) {
    // Lids closing the open rims: pressure only, at the mean pressure of the
    // cells along the rim, with the sheet's sign (the cells' p over P).
    const double sign = sheetSign(tissue, faces, origin);
    std::vector<std::size_t> rim_of(tissue.slots(0), kInvalidIndex);
    const auto lids = rimLoops(tissue);
    std::vector<double> sum(lids.size(), 0.0), count(lids.size(), 0.0);
    for (std::size_t r = 0; r < lids.size(); ++r)
      for (Index v : lids[r]) rim_of[v] = r;
    for (WallId w : tissue.walls()) {
      if (!tissue.isBoundaryWall(w)) continue;
      const std::size_t r = rim_of[tissue.topology().edgeVertices(EdgeId(w.index()))[0].index()];
      if (r == kInvalidIndex) continue;
      sum[r] += pressure[tissue.wallCells(w).front()];
      count[r] += 1.0;
    }
    const std::vector<std::uint8_t> support = membraneSupport(tissue, params);
    const std::vector<std::uint32_t> on = planeMembership(tissue, params);
    for (std::size_t r = 0; r < lids.size(); ++r) {
      // A rim on the fixed base (a dome's) or a fixed boundary adds a constant, and one along symmetry planes
      // through the origin nothing (its cone from the origin lies in them): left out, when every edge is so.
      bool closed = true;
      for (std::size_t i = 0; i < lids[r].size(); ++i) {
        const Index a = lids[r][i], b = lids[r][(i + 1) % lids[r].size()];
        closed = closed && ((support[a] && support[b]) || (on[a] & on[b]) != 0);
      }
      if (closed) continue;
      MembranePolygon lid;
      lid.loop = lids[r];
      lid.elastic = false;
      lid.pressure = sign * (count[r] > 0.0 ? sum[r] / count[r] : 0.0);
      polygons.push_back(std::move(lid));
    }
  }
  if (reset) *reset = resets;
  return FanMembraneModel(x, std::move(polygons), params.material, origin);
}

std::vector<double> membraneCellVolumes(const Tissue& tissue, const FanMembraneModel& model,
                                        const Eigen::VectorXd& x) {
  std::vector<double> v(tissue.cellSlots(), 0.0);
  const std::vector<FaceId> faces = membraneFaces(tissue);
  if (tissue.dim() == 2) {
    for (std::size_t i = 0; i < faces.size(); ++i) v[faces[i].index()] = model.coneVolume(x, i);
    return v;
  }
  std::vector<std::size_t> position(tissue.slots(2), 0);
  for (std::size_t i = 0; i < faces.size(); ++i) position[faces[i].index()] = i;
  for (CellId c : tissue.cells())
    for (const OrientedFace& o : tissue.topology().volumeFaces(tissue.cellVolume(c)))
      v[c.index()] += (o.reversed() ? -1.0 : 1.0) * model.coneVolume(x, position[o.handle().index()]);
  return v;
}

namespace {

struct Principal {
  double high = 0.0, low = 0.0;
  Vec3 direction = Vec3::Zero();
};

// In-plane principal values of a tangent tensor of a surface with unit normal n.
Principal inPlane(const Eigen::Matrix3d& m, const Vec3& n) {
  Vec3 e1 = n.unitOrthogonal();
  const Vec3 e2 = n.cross(e1);
  Eigen::Matrix<double, 3, 2> basis;
  basis << e1, e2;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(basis.transpose() * m * basis);
  return {eig.eigenvalues()[1], eig.eigenvalues()[0], basis * eig.eigenvectors().col(1)};
}

// The largest and smallest of the nonzero principal values of a symmetric tensor.
Principal nonzero(const Eigen::Matrix3d& m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
  const Eigen::Vector3d v = eig.eigenvalues();
  const double scale = v.cwiseAbs().maxCoeff();
  Principal p;
  bool any = false;
  for (int k = 0; k < 3; ++k) {
    if (!(std::abs(v[k]) > 1e-12 * scale)) continue;
    p.low = any ? std::min(p.low, v[k]) : v[k];
    if (!any || v[k] >= p.high) {
      p.high = v[k];
      p.direction = eig.eigenvectors().col(k);
    }
    any = true;
  }
  return p;
}

// Per-cell rest areas of the model's membranes (a 3D cell: the sum of its walls').
std::vector<double> cellRestAreas(const Tissue& tissue, const FanMembraneModel& model,
                                  const std::vector<FaceId>& faces) {
  std::vector<double> a(tissue.cellSlots(), 0.0);
  if (tissue.dim() == 2) {
    for (std::size_t i = 0; i < faces.size(); ++i) a[faces[i].index()] = model.restArea(i);
    return a;
  }
  std::vector<std::size_t> position(tissue.slots(2), 0);
  for (std::size_t i = 0; i < faces.size(); ++i) position[faces[i].index()] = i;
  for (CellId c : tissue.cells())
    for (const OrientedFace& o : tissue.topology().volumeFaces(tissue.cellVolume(c)))
      a[c.index()] += model.restArea(position[o.handle().index()]);
  return a;
}

// The columns of membraneWallOutputNames() in a property store (a 3D tissue's
// walls, a sheet's cells), added when missing (zero, policy Copy), and one
// polygon's values written into a slot of them; the growth rate is written
// after the growth update.
void addPolygonOutputs(PropertyStore& store) {
  for (const char* name : {kWallStressName, kGreenStrainName})
    if (!store.has(name)) store.add<Sym3>(name, Sym3{}, DivisionPolicy::Copy);
  for (const char* name : {kStressDirectionName, kStressMinDirectionName, kStrainDirectionName,
                           kStrainMinDirectionName, kFibreDirectionName})
    if (!store.has(name)) store.add<Vec3>(name, Vec3::Zero(), DivisionPolicy::Copy);
  for (const char* name : {kStressMaxName, kStressMinName, kStrainMaxName, kStrainMinName, kRestAreaName,
                           kGrowthRateName, kPressureLoadName})
    if (!store.has(name)) store.add<double>(name, 0.0, DivisionPolicy::Copy);
}

class PolygonOutputs {
 public:
  explicit PolygonOutputs(PropertyStore& store)
      : stress_((addPolygonOutputs(store), store.get<Sym3>(kWallStressName))),
        strain_(store.get<Sym3>(kGreenStrainName)),
        stress_max_(store.get<double>(kStressMaxName)),
        stress_min_(store.get<double>(kStressMinName)),
        strain_max_(store.get<double>(kStrainMaxName)),
        strain_min_(store.get<double>(kStrainMinName)),
        rest_area_(store.get<double>(kRestAreaName)),
        load_(store.get<double>(kPressureLoadName)),
        stress_dir_(store.get<Vec3>(kStressDirectionName)),
        stress_min_dir_(store.get<Vec3>(kStressMinDirectionName)),
        strain_dir_(store.get<Vec3>(kStrainDirectionName)),
        strain_min_dir_(store.get<Vec3>(kStrainMinDirectionName)),
        fibre_(store.get<Vec3>(kFibreDirectionName)) {}

  void write(std::size_t slot, const FanMembraneModel& model, const Eigen::VectorXd& x, std::size_t i) {
    Vec3 n;
    const Eigen::Matrix3d t = model.meanTension(x, i, &n);
    const Eigen::Matrix3d e = model.meanStrain(x, i);
    const Principal pt = inPlane(t, n), pe = inPlane(e, n);
    stress_[slot] = Sym3::fromMatrix(t);
    strain_[slot] = Sym3::fromMatrix(e);
    stress_max_[slot] = pt.high;
    stress_min_[slot] = pt.low;
    stress_dir_[slot] = pt.direction;
    stress_min_dir_[slot] = n.cross(pt.direction);
    strain_max_[slot] = pe.high;
    strain_min_[slot] = pe.low;
    strain_dir_[slot] = pe.direction;
    strain_min_dir_[slot] = n.cross(pe.direction);
    const Vec3& g = model.polygon(i).fibre;  // zero: none (the first edge of each triangle)
    const Vec3 f = g - g.dot(n) * n;
    fibre_[slot] = f.norm() > 1e-12 * g.norm() ? Vec3(f.normalized()) : Vec3::Zero();
    rest_area_[slot] = model.restArea(i);
    load_[slot] = std::abs(model.polygon(i).pressure);
  }

 private:
  PropertyColumn<Sym3>&stress_, &strain_;
  PropertyColumn<double>&stress_max_, &stress_min_, &strain_max_, &strain_min_, &rest_area_, &load_;
  PropertyColumn<Vec3>&stress_dir_, &stress_min_dir_, &strain_dir_, &strain_min_dir_, &fibre_;
};

}  // namespace

void writeMembraneCellStress(Tissue& tissue, const FanMembraneModel& model, const Eigen::VectorXd& x) {
  PropertyStore& cells = tissue.cellProperties();
  if (!cells.has(kWallStressName)) cells.add<Sym3>(kWallStressName, Sym3{}, DivisionPolicy::Copy);
  if (!cells.has(kStressDirectionName)) cells.add<Vec3>(kStressDirectionName, Vec3::Zero(), DivisionPolicy::Copy);
  auto& stress = cells.get<Sym3>(kWallStressName);
  auto& direction = cells.get<Vec3>(kStressDirectionName);
  auto& stress_max = cellOutput(tissue, kStressMaxName);
  auto& stress_min = cellOutput(tissue, kStressMinName);
  auto& strain_max = cellOutput(tissue, kStrainMaxName);
  auto& strain_min = cellOutput(tissue, kStrainMinName);
  const std::vector<FaceId> faces = membraneFaces(tissue);
  auto write = [&](CellId c, const Eigen::Matrix3d& tension, const Principal& t, const Principal& e) {
    stress[c] = Sym3::fromMatrix(tension);
    stress_max[c] = t.high;
    stress_min[c] = t.low;
    direction[c] = t.direction;
    strain_max[c] = e.high;
    strain_min[c] = e.low;
  };
  if (tissue.dim() == 2) {  // a sheet's membranes are its cells: each gets what a 3D wall gets
    PolygonOutputs outputs(cells);
    for (std::size_t i = 0; i < faces.size(); ++i) outputs.write(faces[i].index(), model, x, i);
    return;
  }
  std::vector<Eigen::Matrix3d> tension(faces.size()), strain(faces.size());
  std::vector<double> area(faces.size());
  std::vector<std::size_t> position(tissue.slots(2), 0);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    position[faces[i].index()] = i;
    tension[i] = model.meanTension(x, i);
    strain[i] = model.meanStrain(x, i);
    area[i] = model.fanArea(x, i);
  }
  for (CellId c : tissue.cells()) {
    Eigen::Matrix3d t = Eigen::Matrix3d::Zero(), e = Eigen::Matrix3d::Zero();
    double a = 0.0;
    for (const OrientedFace& o : tissue.topology().volumeFaces(tissue.cellVolume(c))) {
      const std::size_t i = position[o.handle().index()];
      t += area[i] * tension[i];
      e += area[i] * strain[i];
      a += area[i];
    }
    t /= a;
    e /= a;
    write(c, t, nonzero(t), nonzero(e));
  }
}

const std::vector<std::string>& membraneWallOutputNames() {
  static const std::vector<std::string> names = {
      kWallStressName,  kStressMaxName,     kStressMinName,         kStressDirectionName, kStressMinDirectionName,
      kGreenStrainName, kStrainMaxName,     kStrainMinName,         kStrainDirectionName, kStrainMinDirectionName,
      kFibreDirectionName, kRestAreaName,   kGrowthRateName,        kPressureLoadName};
  return names;
}

void prepareMembranePolygonOutputs(Tissue& tissue) {
  addPolygonOutputs(tissue.dim() == 3 ? tissue.wallProperties() : tissue.cellProperties());
}

void writeMembraneWallOutputs(Tissue& tissue, const FanMembraneModel& model, const Eigen::VectorXd& x) {
  if (tissue.dim() != 3)
    throw MechanicsError("mechanics: per-wall membrane outputs are for a 3D tissue's walls (a sheet's membranes "
                         "are its cells: writeMembraneCellStress)");
  const std::vector<FaceId> faces = membraneFaces(tissue);
  if (model.numPolygons() < faces.size())
    throw MechanicsError("mechanics: the membrane model has " + std::to_string(model.numPolygons()) +
                         " polygons for " + std::to_string(faces.size()) + " walls");
  PolygonOutputs outputs(tissue.wallProperties());
  for (std::size_t i = 0; i < faces.size(); ++i) outputs.write(faces[i].index(), model, x, i);
}

MembraneStepReport membraneGrowthStep(Tissue& tissue, const MembraneGrowthParams& params, MembraneRestState& state,
                                      double dt, std::mt19937_64* rng) {
  params.check();
  if (!(dt >= 0.0 && std::isfinite(dt))) throw InputError("mechanics: step dt " + formatNumber(dt) + " must be >= 0");
  MembraneStepReport report;
  FanMembraneModel model = buildTissueMembranes(tissue, params, state, &report.polygons_reset);
  report.polygons = model.numPolygons();

  const std::vector<std::uint8_t> fixed = membraneFixedDofs(tissue, params);
  for (VertexId v : tissue.vertices()) {
    const std::size_t i = 3 * static_cast<std::size_t>(v.index());
    report.fixed_vertices += fixed[i] && fixed[i + 1] && fixed[i + 2] ? 1 : 0;
    report.fixed_dofs += static_cast<std::size_t>(fixed[i] + fixed[i + 1] + fixed[i + 2]);
  }
  std::string supports = "the membrane support '" + membraneSupports().name(params.support) + "'";
  if (!params.planes.empty()) {
    supports += " with the symmetry planes ";
    for (std::size_t k = 0; k < params.planes.size(); ++k) supports += (k ? ", " : "") + params.planes[k].text();
  }
  requireNoRigidMotion(tissue, fixed, supports, params.solver.context);
  Eigen::VectorXd x = spatialDofs(tissue);
  report.equilibrium = solveEquilibrium(model, x, fixed, params.solver);
  setSpatialDofs(tissue, x);

  const std::vector<FaceId> faces = membraneFaces(tissue);
  if (params.feedback.rate > 0.0 || params.feedback.noise > 0.0) {
    if (params.feedback.noise > 0.0 && !rng) throw InputError("mechanics: feedback noise needs a random stream");
    std::normal_distribution<double> normal(0.0, 1.0);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      Vec3 n;
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(model.meanTension(x, i, &n));
      const Vec3 s = eig.eigenvectors().col(2);  // the largest principal tension
      const double kick = params.feedback.noise > 0.0 ? params.feedback.noise * std::sqrt(dt) * normal(*rng) : 0.0;
      Vec3& f = state.fibres[faces[i].index()];
      if (f.norm() > 0.0) f = turnFibre(f, s, n, params.feedback.rate, dt, kick);
    }
  }
  writeMembraneCellStress(tissue, model, x);
  if (tissue.dim() == 3) writeMembraneWallOutputs(tissue, model, x);
  const std::vector<double> rest_before = cellRestAreas(tissue, model, faces);
  std::vector<double> wall_rest_before(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) wall_rest_before[i] = model.restArea(i);
  // phi per polygon: the cell's (sheet) or the mean of the wall's cells' (3D) extensibility, when the tissue has it.
  std::vector<double> phi(model.numPolygons(), params.growth.extensibility);
  if (tissue.cellProperties().has(kExtensibilityName)) {
    const std::vector<double> wall_phi = wallExtensibilities(tissue, params.growth.extensibility);
    const auto& cell_phi = tissue.cellProperties().get<double>(kExtensibilityName);
    for (std::size_t i = 0; i < faces.size(); ++i)
      phi[i] = tissue.dim() == 2 ? cell_phi[CellId(faces[i].index())] : wall_phi[faces[i].index()];
  }
  report.max_growth_rate = model.growRestShape(x, params.growth, dt, phi);
  const std::vector<double> rest_after = cellRestAreas(tissue, model, faces);
  auto& growth_rate = cellOutput(tissue, kGrowthRateName);
  for (CellId c : tissue.cells()) {
    const double a0 = rest_before[c.index()];
    growth_rate[c] = dt > 0.0 && a0 > 0.0 ? (rest_after[c.index()] - a0) / (a0 * dt) : 0.0;
  }
  if (tissue.dim() == 3) {
    auto& wall_rate = wallOutput(tissue, kGrowthRateName);
    auto& wall_rest = wallOutput(tissue, kRestAreaName);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const WallId w(faces[i].index());
      const double a0 = wall_rest_before[i], a1 = model.restArea(i);
      wall_rate[w] = dt > 0.0 && a0 > 0.0 ? (a1 - a0) / (a0 * dt) : 0.0;
      wall_rest[w] = a1;
    }
  }
  auto& ratio = tissue.properties(2).get<double>(kMembraneRestRatioName);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Index slot = faces[i].index();
    state.rest[slot] = model.restMetrics(i);
    double rest = 0.0, current = 0.0;
    const auto now = FanMembraneModel::currentMetrics(x, state.loops[slot], state.triangulations[slot]);
    for (std::size_t k = 0; k < now.size(); ++k) {
      rest += restArea(state.rest[slot][k]);
      current += restArea(now[k]);
    }
    ratio[faces[i]] = rest / current;
  }
  return report;
}

std::string MembraneRestState::toText(const Tissue& tissue) const {
  std::string text;
  for (FaceId f : membraneFaces(tissue)) {
    if (f.index() >= rest.size()) continue;
    const auto& r = rest[f.index()];
    const MembraneTriangulation tri =
        f.index() < triangulations.size() ? triangulations[f.index()] : MembraneTriangulation{};
    // The mean fan as it always was ("n metrics fibre"); the others name themselves.
    std::ostringstream head;
    if (!text.empty()) head << ' ';
    if (tri.kind == MembraneTriangulation::Kind::KernelFan) {
      head << "apex " << tri.apex_weights.size();
      for (double w : tri.apex_weights) head << ' ' << formatNumber(w);
      head << ' ' << r.size();
    } else if (tri.kind == MembraneTriangulation::Kind::Ears) {
      head << "ears " << tri.ears.size();
      for (const auto& t : tri.ears)
        for (int c : t) head << ' ' << c;
    } else {
      head << r.size();
    }
    text += head.str();
    for (const RestMetric& m : r)
      text += " " + formatNumber(m(0)) + " " + formatNumber(m(1)) + " " + formatNumber(m(2));
    const Vec3 fibre = f.index() < fibres.size() ? fibres[f.index()] : Vec3::Zero();
    text += " " + formatNumber(fibre.x()) + " " + formatNumber(fibre.y()) + " " + formatNumber(fibre.z());
  }
  return text;
}

void MembraneRestState::fromText(const Tissue& tissue, const std::string& text, const std::string& source) {
  std::istringstream in(text);
  auto number = [&](double& v) {
    std::string word;
    if (!(in >> word)) throw InputError(source + ": the membrane rest state ends early");
    const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
    if (r.ec != std::errc() || r.ptr != word.data() + word.size())
      throw InputError(source + ": the membrane rest state holds '" + word + "', not a number");
  };
  loops.assign(tissue.slots(2), {});
  rest.assign(tissue.slots(2), {});
  fibres.assign(tissue.slots(2), Vec3::Zero());
  triangulations.assign(tissue.slots(2), {});
  auto count = [&](std::size_t expected, const char* what, FaceId f) {
    double n = 0.0;
    number(n);
    if (n != static_cast<double>(expected))
      throw InputError(source + ": the membrane rest state has " + formatNumber(n) + " " + what + " for " +
                       faceName(tissue, f) + ", which needs " + std::to_string(expected));
  };
  for (FaceId f : membraneFaces(tissue)) {
    const std::vector<Index> loop = faceLoop(tissue, f);
    MembraneTriangulation& tri = triangulations[f.index()];
    const std::streampos start = in.tellg();
    std::string word;
    in >> word;
    if (word == "apex") {
      tri.kind = MembraneTriangulation::Kind::KernelFan;
      count(loop.size(), "apex weights", f);
      tri.apex_weights.resize(loop.size());
      for (double& w : tri.apex_weights) number(w);
      count(loop.size(), "fan triangles", f);
    } else if (word == "ears") {
      tri.kind = MembraneTriangulation::Kind::Ears;
      count(loop.size() - 2, "ear triangles", f);
      tri.ears.resize(loop.size() - 2);
      for (auto& t : tri.ears)
        for (int& c : t) {
          double v = 0.0;
          number(v);
          c = static_cast<int>(v);
          if (static_cast<double>(c) != v)
            throw InputError(source + ": the membrane rest state has triangle corner " + formatNumber(v) + " for " +
                             faceName(tissue, f));
        }
    } else {
      in.clear();
      in.seekg(start);
      count(loop.size(), "fan triangles", f);
    }
    tri.check(loop.size(), source + ": the membrane rest state of " + faceName(tissue, f));
    loops[f.index()] = loop;
    rest[f.index()].resize(tri.size(loop.size()));
    for (RestMetric& m : rest[f.index()]) {
      number(m(0));
      number(m(1));
      number(m(2));
    }
    for (int k = 0; k < 3; ++k) number(fibres[f.index()][k]);
  }
  std::string extra;
  if (in >> extra) throw InputError(source + ": the membrane rest state has more values than the tissue's polygons");
}

}  // namespace tessella::mechanics
