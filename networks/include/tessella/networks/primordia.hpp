// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Primordia on a dome: where a species (auxin) peaks in the peripheral zone.
// A cell starts a primordium when its concentration is above a threshold and
// above that of every neighbour (a strict local maximum over the graph's
// interfaces), its distance from the apex is in [min_radius, max_radius]
// (the peripheral annulus, measured in a straight line from the summit, not
// along the surface: on a dome it grows along every meridian, also for cells
// that flowed past the base, where the distance from the axis shrinks again),
// and its centroid is at
// least min_separation (straight-line distance) from every existing
// primordium and from the other cells chosen in the same call. Candidates are
// taken by decreasing concentration (ties: graph order), so the result is
// deterministic. Angles are about the axis, counterclockwise looking down it
// from the summit's side, from the reference direction: the x axis projected
// on the plane normal to the axis (the y axis when the axis is along x).
// docs/networks.md, "Phyllotaxis on a growing dome".

#include <vector>

#include "tessella/networks/network_graph.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::networks {

struct PrimordiumOptions {
  double threshold = 0.0;       ///< concentration a peak must exceed
  double min_radius = 0.0;      ///< the peripheral annulus: distance from the apex
  double max_radius = 1e300;
  double min_separation = 0.0;  ///< from every existing primordium
  Vec3 apex = Vec3::Zero();     ///< a point on the axis (the summit)
  Vec3 axis = Vec3(0, 0, 1);    ///< the dome's axis, pointing out of the summit

  /// InputError naming the option at fault (radii, separation, a zero axis).
  void validate() const;
};

/// A point's place about the dome's axis.
struct AxialPosition {
  double angle_deg = 0.0;  ///< in [0, 360)
  double radius = 0.0;     ///< distance from the axis
  double distance = 0.0;   ///< straight-line distance from the apex
};
AxialPosition axialPosition(const Vec3& point, const Vec3& apex, const Vec3& axis);

/// The divergence angle from one primordium to the next: (angle - previous)
/// reduced to [0, 360). A spiral of the golden angle gives 137.5 (or 222.5
/// for the other handedness), a distichous pattern 180.
double divergenceDeg(double previous_angle_deg, double angle_deg);

/// The cells (indices into the graph) that start new primordia, in the
/// order they were chosen; `existing` are the positions of the primordia
/// already there. InputError when `concentration` has not one value per cell.
std::vector<int> findPrimordia(const NetworkGraph& graph, const std::vector<double>& concentration,
                               const PrimordiumOptions& options, const std::vector<Vec3>& existing);

}  // namespace tessella::networks
