// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Membranes built from a tissue's polygons (docs/mechanics.md, "Membranes from
// a tissue"): every polygon (a cell of a curved sheet, a wall of a 3D tissue)
// is cut into triangles by its MembraneTriangulation (fixed at its reference:
// the fan from the mean of its loop vertices, the fan from an apex with fixed
// weights, or ear-clipped triangles), and each triangle is a constant-strain
// membrane element (MembraneMaterial: St Venant-Kirchhoff or neo-Hookean,
// transversely isotropic, the fibre ratio per polygon). The apex is a linear function of the loop vertices,
// a = sum_k w_k x_k (w_k = 1/n for the mean fan), so the degrees of freedom are
// the vertices' positions only (three per vertex slot) and the chain rule
// carries the element forces and tangents at the apex to every loop vertex
// with weight w_k. Pressure work: each polygon f carries a pressure
// coefficient p_f and contributes -p_f V_f, V_f the signed volume of the cone
// from a fixed origin O to its triangles (a, b, c),
//   V_f = (1/6) sum_t (a - O) . ((b - O) x (c - O)).
// A 3D cell's volume is sum_f s_cf V_f over its walls (s_cf its outward sign),
// so p_f = sum_c s_cf P_c; an open sheet's cell c has p_c = P_c (the volume
// between the sheet and the base plane, O on that plane).

#include <array>
#include <vector>

#include <Eigen/Core>

#include "tessella/mechanics/energy_model.hpp"
#include "tessella/mechanics/membrane_model.hpp"
#include "tessella/mechanics/membrane_triangle.hpp"
#include "tessella/mechanics/membrane_triangulation.hpp"
#include "tessella/mechanics/strain_growth.hpp"
#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::mechanics {

/// The rest shape of a triangle (c0, c1, c2) (a fan's: (apex, x_i, x_{i+1})) as
/// its metric in the basis of its two edges from its first corner:
/// (|D1|^2, D1 . D2, |D2|^2) of the rest edge vectors D1 = X_1 - X_0,
/// D2 = X_2 - X_0. Frame-free: the same numbers whatever the triangle's
/// position and orientation.
using RestMetric = Eigen::Vector3d;

struct MembranePolygon {
  std::vector<Index> loop;          ///< vertex slots (dofs 3 slot .. 3 slot + 2), n >= 3
  std::vector<RestMetric> rest;     ///< one per triangle of `triangulation` (the mean fan: n)
  MembraneTriangulation triangulation{};  ///< how the loop is cut into triangles (default: the mean fan)
  Vec3 fibre = Vec3::Zero();        ///< fibre direction (projected on each triangle; zero: its first edge)
  double young_scale = 1.0;         ///< this polygon's E is material.young times this (> 0)
  /// This polygon's fibre ratio (> 0; neo-Hookean >= 1); 0: the material's.
  double fibre_ratio = 0.0;
  double pressure = 0.0;            ///< p_f: the energy has -p_f V_f
  /// false: a lid closing an open rim, pressure only (no elastic energy; `rest` ignored).
  bool elastic = true;
};

class FanMembraneModel final : public EnergyModel {
 public:
  /// `positions`: the configuration the fibre directions are read in (the
  /// current one): each triangle's fibre is projected on its plane there and
  /// pulled back to its rest shape. `num_points`: vertex slots (dofs 3 n).
  /// Throws InputError naming the polygon for a bad loop, a rest metric that is
  /// not positive definite or a degenerate triangle.
  FanMembraneModel(const Eigen::VectorXd& positions, std::vector<MembranePolygon> polygons,
                   MembraneMaterial material, const Vec3& origin);

  Eigen::Index size() const override { return size_; }
  double energy(const Eigen::VectorXd& x) const override;
  void gradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) const override;
  void hessian(const Eigen::VectorXd& x, std::vector<Triplet>& entries) const override;
  double forceScale(const Eigen::VectorXd& x) const override;
  double energyScale(const Eigen::VectorXd& x) const override;

  /// V_f of polygon f at x (the signed cone volume from the origin).
  double coneVolume(const Eigen::VectorXd& x, std::size_t f) const;
  /// Current rest metrics of polygon f's triangles.
  std::vector<RestMetric> restMetrics(std::size_t f) const;
  /// Membrane tension (t / J) F S F^T of triangle i of polygon f at x.
  Eigen::Matrix3d tension(const Eigen::VectorXd& x, std::size_t f, std::size_t i) const;
  /// The mean membrane tension of polygon f at x (current-area-weighted over
  /// its triangles) and the polygon's unit normal (its vector area).
  Eigen::Matrix3d meanTension(const Eigen::VectorXd& x, std::size_t f, Vec3* normal = nullptr) const;
  /// The Green-Lagrange strain of triangle i of polygon f at x, carried to
  /// the current configuration by the rotation of F (polar decomposition):
  /// (1/2) (F F^T - P), P the projector on the triangle's plane. Its nonzero
  /// principal values are those of E = (1/2) (F^T F - I), its principal
  /// directions the current images of E's.
  Eigen::Matrix3d strain(const Eigen::VectorXd& x, std::size_t f, std::size_t i) const;
  /// The mean of strain() over polygon f's triangles (current-area-weighted, as meanTension).
  Eigen::Matrix3d meanStrain(const Eigen::VectorXd& x, std::size_t f) const;
  /// The current area of polygon f's triangles at x.
  double fanArea(const Eigen::VectorXd& x, std::size_t f) const;
  /// The rest area of polygon f's triangles (0 for a lid).
  double restArea(std::size_t f) const;
  /// Lockhart-Ortega growth of every triangle's rest shape along the
  /// principal directions of its stretch at x (as MembraneModel::growRestShape).
  /// `extensibility`: empty, or phi per polygon in place of the law's.
  /// Returns the largest relative rate.
  double growRestShape(const Eigen::VectorXd& x, const StrainGrowthLaw& law, double dt,
                       const std::vector<double>& extensibility = {});
  std::size_t numPolygons() const { return polygons_.size(); }
  /// The number of triangles of polygon f.
  std::size_t numTriangles(std::size_t f) const { return first_element_[f + 1] - first_element_[f]; }
  const MembranePolygon& polygon(std::size_t f) const { return polygons_[f]; }

  /// The rest metrics of the triangles of `loop` at x: the polygon at rest in its shape.
  static std::vector<RestMetric> currentMetrics(const Eigen::VectorXd& x, const std::vector<Index>& loop,
                                                const MembraneTriangulation& triangulation = {});

 private:
  // Corners of triangle i (a fan's: apex, x_i, x_{i+1}): D holds the rest edges from corner 0.
  using Element = MembraneTriangleRest;
  using Mat32 = Eigen::Matrix<double, 3, 2>;
  std::array<Eigen::Vector3d, 3> corners(const Eigen::VectorXd& x, std::size_t f, std::size_t i) const;
  Mat32 deformationGradient(const std::array<Eigen::Vector3d, 3>& c, const Element& e) const;
  // Adds the element and pressure contributions of polygon f: energy, corner
  // gradient per loop vertex (3 n), dense tangent (3n x 3n) when asked.
  // The current-area-weighted mean over polygon f's triangles of per_triangle(i).
  template <class PerTriangle>
  Eigen::Matrix3d fanMean(const Eigen::VectorXd& x, std::size_t f, PerTriangle per_triangle, Vec3* normal) const;
  double polygonTerms(const Eigen::VectorXd& x, std::size_t f, Eigen::VectorXd* grad, Eigen::VectorXd* magnitude,
                      Eigen::MatrixXd* tangent, double* energy_magnitude) const;

  Eigen::Index size_ = 0;
  std::vector<MembranePolygon> polygons_;
  std::vector<std::size_t> first_element_;  // polygons_[f]'s elements: [first_element_[f], first_element_[f + 1])
  std::vector<Element> elements_;
  MembraneMaterial material_;
  std::vector<MembraneElementLaw> laws_;  // per polygon: the material with its fibre ratio and Young's scale
  Vec3 origin_;
};

}  // namespace tessella::mechanics
