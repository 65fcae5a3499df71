// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// GrowthIntegrator: moves every vertex of a tissue with a velocity field over
// one time step, keeps the tissue on its surface (or in z = 0), recomputes
// the geometry and refuses steps that invert or collapse a cell.
//
// Velocities come either from the field at every vertex, or (the PlantGL
// paper's second mode) from the field at control vertices only (default: the
// boundary), the others being interpolated harmonically.
// Schemes: explicit Euler (first order) and Heun (explicit trapezoid, second
// order). With a projection each stage's result is projected, so the scheme
// is a projected Runge-Kutta method; it keeps its order for a field tangent
// to the surface.

#include <memory>
#include <vector>

#include "tessella/growth/harmonic_interpolation.hpp"
#include "tessella/growth/surface_projection.hpp"
#include "tessella/growth/velocity_field.hpp"
#include "tessella/tissue/enum_table.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::growth {

enum class IntegrationScheme { Euler, Heun };
enum class VelocitySource {
  Field,          ///< the field at every vertex
  HarmonicFromControl  ///< the field at control vertices, harmonic interpolation elsewhere
};

/// The names of the schemes: euler, heun (also accepted: rk2).
const EnumTable<IntegrationScheme>& integrationSchemes();
/// The names of the velocity sources: field, boundary (HarmonicFromControl).
const EnumTable<VelocitySource>& velocitySources();

const char* schemeName(IntegrationScheme s);
/// "euler" / "heun" (also "rk2"); InputError naming the value and the known names otherwise.
IntegrationScheme parseScheme(const std::string& name);

struct GrowthOptions {
  IntegrationScheme scheme = IntegrationScheme::Heun;
  VelocitySource source = VelocitySource::Field;
  /// Applied to every vertex after every stage (curved-surface tissues).
  /// Planar tissues are always kept at z = 0.
  SurfaceProjection projection{};
  /// Check every cell after the step and throw GeometryError (positions
  /// restored) if one is inverted or collapsed. A non-finite velocity or
  /// position is a GeometryError (positions restored) either way.
  bool check_inversion = true;
  /// A cell whose area (2D) / volume (3D) is at or below this counts as
  /// collapsed. Inversion is detected independently of it: a planar cell
  /// whose normal turns to -z, a surface cell whose normal turns against its
  /// normal before the step, a 3D cell whose signed volume becomes negative.
  double min_cell_measure = 0.0;
};

class GrowthIntegrator {
 public:
  GrowthIntegrator(std::shared_ptr<const VelocityField> field, GrowthOptions options = {});

  /// Advances the tissue from t.time() to t.time() + dt and sets the clock to
  /// the new time. On any error (a GeometryError, or an exception from the
  /// field or the projection) the positions and the clock are restored.
  /// dt must be positive and finite (InputError otherwise).
  /// Uses the integrator's own geometry cache (geometry()).
  void step(Tissue& t, double dt) { step(t, dt, cache_); }
  /// The same with a shared cache (a Simulation's): the face normals before
  /// the step (surface tissues) are required from it, and it holds the cell
  /// measures (kCellMeasures) of the moved tissue after the step, so a
  /// division stage reading it computes nothing again.
  void step(Tissue& t, double dt, GeometryCache& geometry);

  /// Velocities the integrator uses for the current positions at time `time`
  /// (every vertex slot; dead slots hold zero).
  void velocities(const Tissue& t, std::span<const Vec3> positions, double time,
                  std::span<Vec3> out);

  /// The integrator's own cache: the geometry of the tissue after the last
  /// step(t, dt) (fresh until the tissue is edited again).
  const GeometryCache& geometry() const { return cache_; }
  const GrowthOptions& options() const { return options_; }
  const VelocityField& field() const { return *field_; }
  HarmonicInterpolator& interpolator() { return interpolator_; }

 private:
  void project(const Tissue& t, std::span<Vec3> x) const;
  void checkCells(Tissue& t, const GeometryCache& geometry, double t0, double t1);
  // Non-finite velocities (at alive vertices) and positions are errors naming
  // the field, the vertex, its position and the time.
  GeometryError nonFiniteVelocity(std::size_t vertex, const Vec3& x, const Vec3& v, double time) const;
  void checkVelocities(const Tissue& t, std::span<const Vec3> x, std::span<const Vec3> v, double time) const;
  void checkPositions(Tissue& t, double t0, double t1, std::span<const Vec3> k2);  // k2: Heun's second stage
  void undo(Tissue& t, double t0);  // positions from x0_, clock t0

  std::shared_ptr<const VelocityField> field_;
  GrowthOptions options_;
  HarmonicInterpolator interpolator_;
  GeometryCache cache_;
  // Scratch buffers kept between steps (no per-step allocation).
  std::vector<Vec3> x0_, k1_, k2_, gather_x_, gather_v_;
  std::vector<Vec3> normal_before_;
};

}  // namespace tessella::growth
