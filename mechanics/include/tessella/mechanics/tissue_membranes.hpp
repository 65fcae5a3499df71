// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Membranes from a tissue's walls (docs/mechanics.md, "Membranes from a
// tissue"): a curved sheet (dim 2, Embedding::Surface) has one membrane per
// cell, a 3D tissue one per wall polygon (shared by its two cells). Each is cut
// into membrane triangles (FanMembraneModel) by the triangulation chosen when
// its rest state is created (membrane_triangulation.hpp: the fan from its
// vertex mean, or for a polygon whose fan folds, the fan from its kernel
// centroid with fixed weights or its ear-clipped triangles), kept with the
// rest state while its loop is unchanged. Pressure work: a 3D cell's pressure times its
// volume (the same fans, outward signs); a sheet's cell's pressure times the
// volume of the cone from a point on the base plane (z = z_min of the support,
// under the tissue's centroid) to its fan, signed so that the sheet's total is
// positive: the volume between the sheet and its base plane, up to a constant
// while the base ring is fixed.
//
// The rest shape of every triangle is kept in a MembraneRestState between
// steps, keyed by polygon (face slot) and its loop, with the triangulation. A
// polygon whose loop has changed (divided, or a vertex inserted by a
// neighbour's division) is triangulated anew and starts at rest in its current
// shape scaled isotropically by its previous rest-to-current area ratio (the
// face property membrane_rest_ratio, copied to both parts of a divided face); a
// new face (the wall a 3D division adds) starts at rest.

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "tessella/mechanics/equilibrium.hpp"
#include "tessella/mechanics/fan_membrane_model.hpp"
#include "tessella/mechanics/fibre_feedback.hpp"
#include "tessella/mechanics/strain_growth.hpp"
#include "tessella/tissue/enum_table.hpp"

namespace tessella {
class Tissue;
}

namespace tessella::mechanics {

inline constexpr const char* kMembraneRestRatioName = "membrane_rest_ratio";
inline constexpr const char* kYoungScaleName = "young_scale";
/// Face property (a sheet's cells, a 3D tissue's walls), double: the polygon's
/// fibre ratio when present, else the material's. A model or an initial tissue
/// sets it; division policy Copy (both parts keep it) when the tissue has it.
inline constexpr const char* kFibreRatioName = "fibre_ratio";
inline constexpr const char* kStrainMaxName = "strain_max";    ///< cell, double: larger principal Green strain
inline constexpr const char* kStrainMinName = "strain_min";    ///< cell, double: smaller principal Green strain
inline constexpr const char* kGrowthRateName = "growth_rate";  ///< cell, double: (A1 - A0) / (A0 dt) of its rest area
// The walls of a 3D tissue (wall properties, policy Copy; docs/mechanics.md, "Membrane outputs per wall"). They
// also carry wall_stress (Sym3), stress_max, stress_min, stress_direction, strain_max, strain_min and growth_rate,
// the cells' names for the wall's own values.
inline constexpr const char* kGreenStrainName = "green_strain";  ///< wall, Sym3: mean Green strain (current frame)
inline constexpr const char* kStressMinDirectionName = "stress_min_direction";  ///< wall, Vec3: unit, of stress_min
inline constexpr const char* kStrainDirectionName = "strain_direction";         ///< wall, Vec3: unit, of strain_max
inline constexpr const char* kStrainMinDirectionName = "strain_min_direction";  ///< wall, Vec3: unit, of strain_min
inline constexpr const char* kFibreDirectionName = "fibre_direction";  ///< wall, Vec3: unit fibre in its plane, or 0
inline constexpr const char* kRestAreaName = "rest_area";              ///< wall, double: its triangles' rest area
inline constexpr const char* kPressureLoadName = "pressure_load";      ///< wall, double: |sum_c s_cf P_c|

/// How each polygon's fibre direction is chosen (at its centroid c).
struct FibreRule {
  enum class Kind { None, Fixed, Circumferential };
  Kind kind = Kind::None;
  Vec3 vector = Vec3(0, 0, 1);  ///< Fixed: this direction; Circumferential: the axis direction
  Vec3 point = Vec3::Zero();    ///< Circumferential: a point on the axis
  /// The direction for a polygon with centroid c (zero: none).
  Vec3 at(const Vec3& c) const;
};

/// A symmetry plane normal to a coordinate axis: x[axis] = offset. A vertex
/// within MembraneGrowthParams::plane_distance of it keeps that coordinate
/// (its normal displacement is zero; it slides in the plane).
struct SymmetryPlane {
  int axis = 0;  ///< 0: x, 1: y, 2: z
  double offset = 0.0;
  /// "x = 0" (exact text: reads back with parseSymmetryPlanes).
  std::string text() const;
};

/// Planes from text such as "x = 0, y = 0" (items "x=c", "y=c" or "z=c"
/// separated by commas; empty: none). InputError naming `source` and the item.
std::vector<SymmetryPlane> parseSymmetryPlanes(const std::string& text, const std::string& source);

struct MembraneGrowthParams {
  MembraneMaterial material{};
  double pressure = 0.1;  ///< turgor of cells without a turgor_pressure value
  FibreRule fibres{};
  /// Stress feedback (off at rate 0 and noise 0): each polygon keeps its own
  /// fibre (from `fibres` when it has none), turned toward its maximal
  /// principal stress every step (fibre_feedback.hpp).
  FibreFeedback feedback{};
  StrainGrowthLaw growth{};
  /// What is fixed (the names: membraneSupports()): `Base`, the vertices within `base_distance` above the
  /// base height (`base_height`, else the lowest vertex z: the base ring of a
  /// dome or a cylinder, the bottom of a 3D tissue); `Boundary`, every vertex on a boundary wall of a sheet (its rims:
  /// a cropped patch of a larger surface); `Point`, the one-point support of a
  /// closed body (fixPointSupport: the fewest components of three vertices that
  /// remove the rigid motions the planes leave); `Symmetry`, the planes alone.
  /// The symmetry `planes` apply with every support. A rim each of whose edges
  /// is fixed or lies in a symmetry plane gets no lid (its pressure work is
  /// constant, or zero: a sheet's cone origin lies on every plane).
  enum class Support { Base, Boundary, Point, Symmetry };
  Support support = Support::Base;
  double base_distance = 1e-6;
  std::vector<SymmetryPlane> planes;
  double plane_distance = 1e-6;
  /// `Point`: the anchor is the vertex nearest this point (unset: the vertex
  /// mean of the tissue as it is; a run sets it once, at its start).
  std::optional<Vec3> point;
  /// The base plane's z for `Base`. A run sets it once, at its start: found
  /// again each step, a free rim vertex that sank below the base would become
  /// the "lowest vertex" and the support would hold it alone.
  std::optional<double> base_height;
  EquilibriumOptions solver{};
  void check() const;
};

/// Rest metrics of every membrane polygon between steps (by face slot).
struct MembraneRestState {
  std::vector<std::vector<Index>> loops;
  std::vector<std::vector<RestMetric>> rest;
  /// Per face slot, how its loop is cut into the triangles `rest` describes.
  std::vector<MembraneTriangulation> triangulations;
  /// Per face slot, the fibre direction under stress feedback (zero: none yet).
  std::vector<Vec3> fibres;
  /// Text for a snapshot's run state: per live membrane face in slot order, its
  /// triangle count, its rest metrics and its fibre (exact text); a kernel fan
  /// is preceded by "apex n" and its n weights, ears are "ears t" and their 3 t
  /// corners (loop positions) in place of the count.
  std::string toText(const Tissue& tissue) const;
  /// Reads toText's output back for `tissue` (same faces, same loops);
  /// InputError naming `source` on a mismatch.
  void fromText(const Tissue& tissue, const std::string& text, const std::string& source);
};

struct MembraneStepReport {
  EquilibriumReport equilibrium;
  std::size_t polygons = 0;
  std::size_t polygons_reset = 0;  ///< polygons whose rest shape was (re)initialised
  std::size_t fixed_vertices = 0;  ///< vertices with all three dofs fixed
  std::size_t fixed_dofs = 0;      ///< fixed dofs of live vertices (supports and symmetry planes)
  double max_growth_rate = 0.0;
};

/// The names of the supports (`mechanics.membrane_support`): base, boundary, point, symmetry.
const EnumTable<MembraneGrowthParams::Support>& membraneSupports();

/// The faces that are membranes: a sheet's cells, a 3D tissue's walls.
/// MechanicsError for a planar tissue (use the wall-spring model).
std::vector<FaceId> membraneFaces(const Tissue& tissue);
/// Positions as dofs: (x, y, z) per vertex slot.
Eigen::VectorXd spatialDofs(const Tissue& tissue);
void setSpatialDofs(Tissue& tissue, const Eigen::VectorXd& x);
/// The pressure coefficient of every membrane face (see the header comment)
/// from per-cell-slot pressures; `origin` the cone apex of a sheet.
std::vector<double> facePressures(const Tissue& tissue, const std::vector<FaceId>& faces,
                                  const std::vector<double>& cell_pressure, const Vec3& origin);
/// The cone origin of a sheet: the tissue's vertex mean dropped to z_min.
Vec3 sheetOrigin(const Tissue& tissue);
/// The cone origin the membranes use: a sheet's sheetOrigin moved onto every
/// symmetry plane (MechanicsError for a sheet with two parallel planes apart);
/// the origin for a 3D tissue (its cells are closed).
Vec3 membraneOrigin(const Tissue& tissue, const MembraneGrowthParams& params);
/// The fixed degrees of freedom of the supports and symmetry planes, three
/// per vertex slot (x, y, z; 1: fixed; dead slots fixed). Does not check the
/// rigid motions (requireNoRigidMotion; membraneGrowthStep does).
/// MechanicsError for Boundary on a 3D tissue or a sheet without a rim.
std::vector<std::uint8_t> membraneFixedDofs(const Tissue& tissue, const MembraneGrowthParams& params);
/// The fully fixed vertices (per vertex slot, 1: all three dofs fixed) of membraneFixedDofs.
std::vector<std::uint8_t> membraneSupport(const Tissue& tissue, const MembraneGrowthParams& params);
/// Builds the model of `tissue` as it is, rest shapes from `state` (updated
/// for changed loops, with a new triangulation; counts them in `reset`).
FanMembraneModel buildTissueMembranes(Tissue& tissue, const MembraneGrowthParams& params,
                                      MembraneRestState& state, std::size_t* reset = nullptr);
/// Cell volumes (3D) or cone volumes (sheet) of the model's fans at x, by cell slot.
std::vector<double> membraneCellVolumes(const Tissue& tissue, const FanMembraneModel& model, const Eigen::VectorXd& x);

/// The per-cell outputs of the membranes at x (docs/mechanics.md, "Membrane
/// outputs"). A sheet's cell is a membrane: it gets its fan's values of every
/// column of membraneWallOutputNames() but the growth rate (written after the
/// growth update), as a 3D wall does. A 3D cell gets the mean over its walls'
/// fans weighted by their current areas of the mean tension (wall_stress;
/// stress_max, stress_min, stress_direction: the largest and smallest nonzero
/// principal values) and of the mean Green strain (strain_max, strain_min).
/// Columns added with policy Copy when missing.
void writeMembraneCellStress(Tissue& tissue, const FanMembraneModel& model, const Eigen::VectorXd& x);

/// The wall properties membraneGrowthStep writes on a 3D tissue's walls, in
/// the order of a walls file (docs/mechanics.md, "Membrane outputs per wall").
const std::vector<std::string>& membraneWallOutputNames();

/// Adds the columns of membraneWallOutputNames() (zero, policy Copy) that the
/// membranes do not have yet: a 3D tissue's walls (what a walls file shows
/// before the first step) or a sheet's cells (writeMembraneCellStress fills
/// them for a sheet).
void prepareMembranePolygonOutputs(Tissue& tissue);

/// The per-wall outputs of a 3D tissue's membranes at x (each wall polygon's
/// own, docs/mechanics.md "Membrane outputs per wall"): the mean tension
/// N = sum_i a_i N_i / sum_i a_i over its triangles (a_i their current
/// areas; wall_stress), its principal values in the wall's plane (normal: the
/// wall's vector area; stress_max, stress_min) with their unit directions
/// (stress_direction, stress_min_direction = n x stress_direction), the same
/// for the mean Green strain (green_strain, strain_max, strain_min,
/// strain_direction, strain_min_direction), the fibre the model uses
/// projected on the wall's plane (fibre_direction; 0 when none), its rest area
/// (rest_area) and the pressure it carries (pressure_load, |p_f|). Columns
/// added with policy Copy when missing. MechanicsError unless the tissue is 3D
/// and `model` is its membranes (one polygon per wall, in membraneFaces order).
void writeMembraneWallOutputs(Tissue& tissue, const FanMembraneModel& model, const Eigen::VectorXd& x);

/// One step: model from the tissue, supports (membraneFixedDofs; a
/// MechanicsError naming the free rigid motions when they leave any, before
/// anything moves), equilibrium (positions move there;
/// EquilibriumError leaves the tissue unchanged), rest shapes grow over dt.
/// With stress feedback, the fibres turn after the equilibrium (noise drawn
/// from `rng`, which must be given when params.feedback.noise > 0). Writes
/// the cells' outputs at the equilibrium (writeMembraneCellStress) and their
/// growth_rate: the relative change of a cell's rest area (its fan's, or the
/// sum of its walls') by this step's growth, divided by dt (0 when dt = 0).
/// A 3D tissue's walls get writeMembraneWallOutputs at the equilibrium, then
/// their own growth_rate and rest_area (after the growth).
MembraneStepReport membraneGrowthStep(Tissue& tissue, const MembraneGrowthParams& params, MembraneRestState& state,
                                      double dt, std::mt19937_64* rng = nullptr);

}  // namespace tessella::mechanics
