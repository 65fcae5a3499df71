// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/growth_integrator.hpp"

#include <cmath>
#include <string>

#include "tessella/growth/parallel_threshold.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/resize_discarding.hpp"

namespace tessella::growth {

const EnumTable<IntegrationScheme>& integrationSchemes() {
  static const EnumTable<IntegrationScheme> table(
      "integration scheme",
      {{"euler", IntegrationScheme::Euler, "Explicit Euler (first order)."},
       {"heun", IntegrationScheme::Heun, "Heun (second order, two field evaluations per step)."}},
      {{"rk2", IntegrationScheme::Heun}});
  return table;
}

const EnumTable<VelocitySource>& velocitySources() {
  static const EnumTable<VelocitySource> table(
      "velocity source",
      {{"field", VelocitySource::Field, "Every vertex moves with the field."},
       {"boundary", VelocitySource::HarmonicFromControl,
        "The field is evaluated on the boundary vertices only and interior velocities are interpolated "
        "harmonically (uniform-weight graph Laplacian), the paper's second mode."}});
  return table;
}

const char* schemeName(IntegrationScheme s) { return integrationSchemes().name(s).c_str(); }

IntegrationScheme parseScheme(const std::string& name) { return integrationSchemes().parse(name); }

namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

/// The lowest slot i with alive[i] and a non-finite v[i], or v.size() (a
/// deterministic report for any thread count).
std::size_t firstNonFinite(std::span<const Vec3> v, const std::vector<std::uint8_t>& alive) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(v.size());
  std::ptrdiff_t bad = n;
#pragma omp parallel for schedule(static, kInterleavedChunk) reduction(min : bad) if(n >= kParallelMinItems)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    if (alive[i] && !finite(v[i]) && i < bad) bad = i;
  return static_cast<std::size_t>(bad);
}

// Positions, velocities and times in these messages are computed: six significant digits say enough.
constexpr int kDigits = 6;

std::string number(double x) { return formatNumber(x, kDigits); }
std::string vec(const Vec3& v) { return formatPoint(v, kDigits); }

}  // namespace

GrowthIntegrator::GrowthIntegrator(std::shared_ptr<const VelocityField> field, GrowthOptions options)
    : field_(std::move(field)), options_(std::move(options)) {
  if (!field_) throw InputError("growth integrator: no velocity field");
}

void GrowthIntegrator::velocities(const Tissue& t, std::span<const Vec3> x, double time,
                                  std::span<Vec3> out) {
  if (options_.source == VelocitySource::Field) {
    field_->velocities(x, time, out);
    return;
  }
  // Field at the control vertices only, harmonic interpolation elsewhere.
  const std::vector<VertexId>& control = interpolator_.controlVertices(t);
  gather_x_.resize(control.size());
  gather_v_.resize(control.size());
  for (std::size_t i = 0; i < control.size(); ++i) gather_x_[i] = x[control[i].index()];
  field_->velocities(gather_x_, time, gather_v_);
  for (std::size_t i = 0; i < control.size(); ++i)
    if (!finite(gather_v_[i])) throw nonFiniteVelocity(control[i].index(), gather_x_[i], gather_v_[i], time);
  std::fill(out.begin(), out.end(), Vec3::Zero());
  for (std::size_t i = 0; i < control.size(); ++i) out[control[i].index()] = gather_v_[i];
  interpolator_.interpolate(t, out);
}

GeometryError GrowthIntegrator::nonFiniteVelocity(std::size_t vertex, const Vec3& x, const Vec3& v,
                                                  double time) const {
  std::string msg = "the velocity field " + field_->describe() + " is not finite at vertex " +
                    std::to_string(vertex) + ", position " + vec(x) + ", t = " + number(time) + ": velocity " + vec(v);
  for (int c = 0; c < 3; ++c) {
    const std::string component = field_->describeComponent(c);
    if (!std::isfinite(v[c]) && !component.empty()) msg += "; " + component + " gives " + number(v[c]);
  }
  return GeometryError(msg, ElementId{0, static_cast<Index>(vertex)});
}

void GrowthIntegrator::checkVelocities(const Tissue& t, std::span<const Vec3> x, std::span<const Vec3> v,
                                       double time) const {
  const std::size_t bad = firstNonFinite(v, t.topology().aliveFlags(0));
  if (bad < v.size()) throw nonFiniteVelocity(bad, x[bad], v[bad], time);
}

void GrowthIntegrator::undo(Tissue& t, double t0) {
  std::span<Vec3> x = t.mutablePositions();
  std::copy(x0_.begin(), x0_.end(), x.begin());
  t.setTime(t0);  // restoring the positions bumped the geometry version: caches of the step are stale
}

void GrowthIntegrator::checkPositions(Tissue& t, double t0, double t1, std::span<const Vec3> k2) {
  const std::span<const Vec3> x = t.positions();
  const std::size_t bad = firstNonFinite(x, t.topology().aliveFlags(0));
  if (bad == x.size()) return;
  const std::string msg = "growth step from t = " + number(t0) + " to t = " + number(t1) + " (dt = " +
                          number(t1 - t0) + ") moved vertex " + std::to_string(bad) + " from " + vec(x0_[bad]) +
                          " to the non-finite position " + vec(x[bad]) + " (velocity " +
                          vec(k2.empty() ? k1_[bad] : Vec3(0.5 * (k1_[bad] + k2[bad]))) + " of the velocity field " +
                          field_->describe() + "); positions restored";  // by step()
  throw GeometryError(msg, ElementId{0, static_cast<Index>(bad)});
}

void GrowthIntegrator::project(const Tissue& t, std::span<Vec3> x) const {
  // Curved sheets only: planar tissues are flattened in the update loops.
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(x.size());
  if (options_.projection) {
    const auto& alive = t.topology().aliveFlags(0);
#pragma omp parallel for schedule(static, kInterleavedChunk) if(n >= kParallelMinItems)
    for (std::ptrdiff_t i = 0; i < n; ++i)
      if (alive[i]) x[i] = options_.projection(x[i]);
  }
}

void GrowthIntegrator::step(Tissue& t, double dt, GeometryCache& geometry) {
  if (!(dt > 0) || !std::isfinite(dt))
    throw InputError("growth step: dt = " + formatNumber(dt) + " must be positive and finite");
  const double t0 = t.time(), t1 = t0 + dt;
  const std::size_t n = t.slots(0);
  // Both are rewritten every step (x0_ by the first update sweep, k1_ by the
  // field), so a growing tissue's arrays are not copied when they move.
  resizeDiscarding(x0_, n);
  resizeDiscarding(k1_, n);

  // Surface cells are checked against their orientation before the step.
  // (From the cache, fresh since the last step unless the tissue changed:
  // the same kernel as polygonMeasures, so the same normals.)
  if (options_.check_inversion && t.embedding() == Embedding::Surface)
    normal_before_ = geometry.require(t, GeometryQuantity::FaceMeasures).face_normal;

  // A non-finite velocity or position is an error whatever check_inversion
  // says: it would poison the tissue (and every snapshot written after).
  velocities(t, t.positions(), t0, k1_);
  checkVelocities(t, t.positions(), k1_, t0);
  std::span<Vec3> x = t.mutablePositions();  // bumps the geometry counter
  const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(n);
  // One sweep keeps x0 (for Heun and for undoing a refused step) and moves
  // the vertices; planar tissues are put back at z = 0 in the same sweep.
  const bool planar = t.embedding() == Embedding::Planar;
#pragma omp parallel for schedule(static, kInterleavedChunk) if(m >= kParallelMinItems)
  for (std::ptrdiff_t i = 0; i < m; ++i) {
    x0_[i] = x[i];
    x[i] = x0_[i] + dt * k1_[i];
    if (planar) x[i].z() = 0.0;
  }
  // From here on any failure (a refused step, an exception from a field or a
  // projection written in Python) leaves the tissue as it was: positions and clock.
  try {
    if (!planar) project(t, x);
    checkPositions(t, t0, t1, {});
    if (options_.scheme == IntegrationScheme::Heun) {
      // Heun: predictor x1 = x0 + dt k1 (above), corrector x0 + dt/2 (k1 + v(x1, t1)).
      resizeDiscarding(k2_, n);
      velocities(t, x, t1, k2_);
      checkVelocities(t, x, k2_, t1);
#pragma omp parallel for schedule(static, kInterleavedChunk) if(m >= kParallelMinItems)
      for (std::ptrdiff_t i = 0; i < m; ++i) {
        x[i] = x0_[i] + (0.5 * dt) * (k1_[i] + k2_[i]);
        if (planar) x[i].z() = 0.0;
      }
      if (!planar) project(t, x);
      checkPositions(t, t0, t1, k2_);
    }
    t.setTime(t1);
    geometry.require(t, kCellMeasures);
    if (options_.check_inversion) checkCells(t, geometry, t0, t1);
  } catch (...) {
    undo(t, t0);
    throw;
  }
}

void GrowthIntegrator::checkCells(Tissue& t, const GeometryCache& geometry, double t0, double t1) {
  const int dim = t.dim();
  const Embedding emb = t.embedding();
  const std::ptrdiff_t nc = static_cast<std::ptrdiff_t>(t.cellSlots());
  const auto& alive = t.topology().aliveFlags(dim);
  std::ptrdiff_t bad = nc;  // lowest offending cell slot (deterministic report)
#pragma omp parallel for schedule(static, kInterleavedChunk) reduction(min : bad) if(nc >= kParallelMinItems)
  for (std::ptrdiff_t c = 0; c < nc; ++c) {
    if (!alive[c]) continue;
    bool wrong;
    if (dim == 3) {
      wrong = !(geometry.volume[c] > options_.min_cell_measure);
    } else {
      const Vec3 ref = emb == Embedding::Planar ? Vec3::UnitZ() : normal_before_[c];
      wrong = !(geometry.face_area[c] > options_.min_cell_measure) ||
              !(geometry.face_normal[c].dot(ref) > 0);
    }
    if (wrong && c < bad) bad = c;
  }
  if (bad == nc) return;

  const CellId cell(static_cast<Index>(bad));
  std::string msg = "growth step from t = " + number(t0) + " to t = " + number(t1) + " (dt = " + number(t1 - t0) +
                    ") inverted or collapsed cell " + std::to_string(bad) + " (lineage id " +
                    std::to_string(t.lineageId(cell)) + "): ";
  // One convention in both dimensions (docs/ARCHITECTURE.md): the signed
  // measure, negative for an inverted cell. A polygon's area is signed
  // against the reference normal (+z, or the cell's normal before the step).
  if (dim == 3) {
    msg += "signed volume " + number(geometry.volume[bad]);
  } else {
    const Vec3 ref = emb == Embedding::Planar ? Vec3::UnitZ() : normal_before_[bad];
    const bool turned = !(geometry.face_normal[bad].dot(ref) > 0);
    msg += "signed area " + number(turned ? -geometry.face_area[bad] : geometry.face_area[bad]);
    if (turned)
      msg += " (normal " + vec(geometry.face_normal[bad]) +
             (emb == Embedding::Planar ? " instead of +z)" : " turned against its previous normal)");
  }
  msg += "; positions restored, try a smaller dt";  // by step()
  throw GeometryError(msg, ElementId{dim, static_cast<Index>(bad)});
}

}  // namespace tessella::growth
