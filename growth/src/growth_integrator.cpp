#include "tessella/growth/growth_integrator.hpp"

#include <cmath>
#include <sstream>

#include "tessella/growth/parallel_threshold.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::growth {

const char* schemeName(IntegrationScheme s) {
  return s == IntegrationScheme::Euler ? "euler" : "heun";
}

IntegrationScheme parseScheme(const std::string& name) {
  if (name == "euler") return IntegrationScheme::Euler;
  if (name == "heun" || name == "rk2") return IntegrationScheme::Heun;
  throw InputError("unknown integration scheme '" + name + "' (expected euler, heun or rk2)");
}

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
  std::fill(out.begin(), out.end(), Vec3::Zero());
  for (std::size_t i = 0; i < control.size(); ++i) out[control[i].index()] = gather_v_[i];
  interpolator_.interpolate(t, out);
}

void GrowthIntegrator::project(const Tissue& t, std::span<Vec3> x) const {
  // Curved sheets only: planar tissues are flattened in the update loops.
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(x.size());
  if (options_.projection) {
    const auto& alive = t.topology().aliveFlags(0);
#pragma omp parallel for schedule(static) if(n >= kParallelMinItems)
    for (std::ptrdiff_t i = 0; i < n; ++i)
      if (alive[i]) x[i] = options_.projection(x[i]);
  }
}

void GrowthIntegrator::step(Tissue& t, double dt) {
  if (!(dt > 0) || !std::isfinite(dt))
    throw InputError("growth step: dt = " + std::to_string(dt) + " must be positive and finite");
  const double t0 = t.time(), t1 = t0 + dt;
  const std::size_t n = t.slots(0);
  x0_.resize(n);  // filled by the first update sweep
  k1_.resize(n);

  // Surface cells are checked against their orientation before the step.
  if (options_.check_inversion && t.embedding() == Embedding::Surface) {
    normal_before_.assign(t.slots(2), Vec3::Zero());
    const auto& alive = t.topology().aliveFlags(2);
    const std::ptrdiff_t nf = static_cast<std::ptrdiff_t>(t.slots(2));
#pragma omp parallel for schedule(static) if(nf >= kParallelMinItems)
    for (std::ptrdiff_t f = 0; f < nf; ++f)
      if (alive[f]) normal_before_[f] = polygonMeasures(t, FaceId(static_cast<Index>(f))).normal;
  }

  velocities(t, t.positions(), t0, k1_);
  std::span<Vec3> x = t.mutablePositions();  // bumps the geometry counter
  const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(n);
  // One sweep keeps x0 (for Heun and for undoing a refused step) and moves
  // the vertices; planar tissues are put back at z = 0 in the same sweep.
  const bool planar = t.embedding() == Embedding::Planar;
#pragma omp parallel for schedule(static) if(m >= kParallelMinItems)
  for (std::ptrdiff_t i = 0; i < m; ++i) {
    x0_[i] = x[i];
    x[i] = x0_[i] + dt * k1_[i];
    if (planar) x[i].z() = 0.0;
  }
  if (!planar) project(t, x);
  if (options_.scheme == IntegrationScheme::Heun) {
    // Heun: predictor x1 = x0 + dt k1 (above), corrector x0 + dt/2 (k1 + v(x1, t1)).
    k2_.resize(n);
    velocities(t, x, t1, k2_);
#pragma omp parallel for schedule(static) if(m >= kParallelMinItems)
    for (std::ptrdiff_t i = 0; i < m; ++i) {
      x[i] = x0_[i] + (0.5 * dt) * (k1_[i] + k2_[i]);
      if (planar) x[i].z() = 0.0;
    }
    if (!planar) project(t, x);
  }
  t.setTime(t1);
  recomputeGeometry(t, cache_, GeometryOptions{.edges = false, .second_moments = false});
  if (options_.check_inversion) checkCells(t, t0, t1);
}

void GrowthIntegrator::checkCells(Tissue& t, double t0, double t1) {
  const int dim = t.dim();
  const Embedding emb = t.embedding();
  const std::ptrdiff_t nc = static_cast<std::ptrdiff_t>(t.cellSlots());
  const auto& alive = t.topology().aliveFlags(dim);
  std::ptrdiff_t bad = nc;  // lowest offending cell slot (deterministic report)
#pragma omp parallel for schedule(static) reduction(min : bad) if(nc >= kParallelMinItems)
  for (std::ptrdiff_t c = 0; c < nc; ++c) {
    if (!alive[c]) continue;
    bool wrong;
    if (dim == 3) {
      wrong = !(cache_.volume[c] > options_.min_cell_measure);
    } else {
      const Vec3 ref = emb == Embedding::Planar ? Vec3::UnitZ() : normal_before_[c];
      wrong = !(cache_.face_area[c] > options_.min_cell_measure) ||
              !(cache_.face_normal[c].dot(ref) > 0);
    }
    if (wrong && c < bad) bad = c;
  }
  if (bad == nc) return;

  const CellId cell(static_cast<Index>(bad));
  std::ostringstream msg;
  msg << "growth step from t = " << t0 << " to t = " << t1 << " (dt = " << (t1 - t0)
      << ") inverted or collapsed cell " << bad << " (lineage id " << t.lineageId(cell) << "): ";
  if (dim == 3) {
    msg << "signed volume " << cache_.volume[bad];
  } else {
    msg << "area " << cache_.face_area[bad] << ", normal (" << cache_.face_normal[bad].transpose()
        << ")" << (emb == Embedding::Planar ? " instead of +z" : " turned against its previous normal");
  }
  msg << "; positions restored, try a smaller dt";
  // Leave the tissue as it was before the step.
  std::span<Vec3> x = t.mutablePositions();
  std::copy(x0_.begin(), x0_.end(), x.begin());
  t.setTime(t0);
  cache_ = GeometryCache{};
  throw GeometryError(msg.str(), ElementId{dim, static_cast<Index>(bad)});
}

}  // namespace tessella::growth
