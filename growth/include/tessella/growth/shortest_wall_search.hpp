// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Local minima of the new wall's measure over the orientations of planes
// through a point (the centroid): the candidate walls of the shortest-wall
// rule (Errera) and of the stochastic rule of Besson and Dumais.
//
// 2D: the length L(theta) is pi-periodic and, between the angles where the
// line passes through a loop vertex (the crossed edges change only there),
// the chord joins two fixed edges and L is strictly convex when the point
// lies on the chord. So [0, pi) is cut at the n vertex angles, each piece's
// minimum is found by safeguarded Newton on L' (or is a piece end), and the
// local minima are exact to `angle_tolerance`: a minimisation over all
// directions, O(n) pieces per cell. For a point outside some chord (very
// concave cells) L is sampled at `samples` angles and each sampled minimum
// refined by Brent's method.
// 3D: the section area A(n) over the sphere of normals is C1 where the cell
// is convex and smooth between the great circles where the plane passes
// through a vertex; it is minimised by descents with its exact gradient
// (NewWallMeasure::measureAndGradient), a Riemannian BFGS with backtracking,
// from 13 starts (the directions of a cube's faces, edges and corners, so
// every orientation is within 28 degrees of a start), lowest area first. A
// descent stops when the quadratic model predicts less than
// `area_tolerance` (relative) of further decrease and the gradient step
// |g| / A is below 1e-10 rad, or when no step lowers A above rounding; the
// point is then probed 1e-3 rad away in six directions, whose second
// differences give the Hessian: it is kept only when no probe is lower and
// no curvature is negative (below -1e-6 A), else the descent leaves the
// saddle and goes on.
// A descent that comes within 0.05 rad of a minimum found before, heading
// towards it, joins it; minima closer than `merge_angle` merge. A minimum
// within 1e-7 rad of a start whose area is no larger to rounding is that
// start exactly (near a symmetry plane the gradient is ill-conditioned).

#include <vector>

#include "tessella/growth/new_wall_measure.hpp"

namespace tessella::growth {

struct WallCandidate {
  Vec3 normal;     ///< unit plane normal
  double measure;  ///< length (2D) or area (3D) of the new wall
  double theta = 0;  ///< 2D only: angle of the normal from the frame's e1
};

struct ShortestWallSearchOptions {
  int samples = 36;                ///< 2D sampled fallback: angles over [0, pi)
  double angle_tolerance = 1e-12;  ///< 2D: Newton / Brent stop at this step (rad)
  double area_tolerance = 1e-12;   ///< 3D: relative decrease still predicted at a minimum
  int max_iterations = 400;        ///< 3D: iterations per descent
  double merge_angle = 1e-3;       ///< minima within this angle (rad) are one
};

/// All local minima found, by increasing measure (at least one).
std::vector<WallCandidate> newWallLocalMinima(const NewWallMeasure& m,
                                              const ShortestWallSearchOptions& options = {});

/// Brent's minimisation of f on [a, b] (f unimodal there), to tolerance tol
/// on x. Returns the abscissa of the minimum.
template <typename F>
double brentMinimize(F&& f, double a, double b, double tol, int max_iterations = 200);

}  // namespace tessella::growth

#include "tessella/growth/detail/brent.ipp"
