// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// DivisionScheduler: each step, divides every cell over its size threshold
// with the division rule (Tissue::splitCell applies property policies and
// lineage; daughters are born at the tissue clock's time). A cell divides at
// most once per step; a daughter still over threshold divides at the next.
//
// Degenerate cuts: when splitCell refuses a plane (GeometryError: it runs
// along a wall, through a vertex it cannot snap to, or leaves a sliver), the
// plane is retried rotated about the cell normal (2D) / tilted (3D) by
// retry_angle and shifted by retry_shift x cell size, alternating sides, up
// to max_attempts in all; then the cell is skipped for this step and listed
// in the report (it is tried again next step).
//
// Crossing walls (3D): a plane whose new wall, cut wall pieces or walls given
// a vertex would cross another wall (division_crossings.hpp) is refused like
// a degenerate cut. Each of the rule's planes (DivisionRule::planes(): for
// shortest_wall every local minimum, smallest first) is tried with its
// retries before the next.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tessella/growth/division_rule.hpp"
#include "tessella/growth/size_threshold.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella {
struct CellSplitPlan2D;
}

namespace tessella::growth {

struct DivisionOptions {
  SplitOptions split{};     ///< passed to Tissue::splitCell
  int max_attempts = 5;     ///< planes tried per cell (the rule's, then perturbed ones)
  double retry_angle = 0.02;  ///< rad
  double retry_shift = 0.01;  ///< relative to the cell size (sqrt(area) / cbrt(volume))
  std::uint64_t seed = 1;   ///< seeds the scheduler's random engine
  /// Tag new walls with the mother's lineage id (division_walls.hpp).
  bool tag_walls = true;
  /// When set, a cell over its threshold divides only if gate(t, c) is true
  /// (e.g. a morphogen's concentration in the cell exceeds a value).
  std::function<bool(const Tissue&, CellId)> gate;
};

struct SkippedDivision {
  CellId cell;
  std::int64_t lineage = -1;
  std::string reason;  ///< the last GeometryError's message
};

struct DivisionRecord {
  std::int64_t mother_lineage = -1;
  CellId cell;      ///< the mother's handle, now the daughter on the negative side
  CellId daughter;  ///< the new cell
  WallId wall;      ///< the new wall
  int attempts = 1; ///< planes tried: 1 if the rule's own plane worked
};

struct DivisionReport {
  std::vector<DivisionRecord> divided;
  std::vector<SkippedDivision> skipped;
};

class DivisionScheduler {
 public:
  DivisionScheduler(SizeThreshold trigger, std::shared_ptr<const DivisionRule> rule,
                    DivisionOptions options = {});

  /// Divides every due cell. The cell measures are required from `geometry`
  /// (shared with the integrator, they are fresh after its step and nothing
  /// is computed again); the divisions leave it stale.
  DivisionReport step(Tissue& t, GeometryCache& geometry) { return step(t, geometry, rng_); }
  /// The same, drawing from a caller's random stream (a simulation's single
  /// stream, so a run is reproducible from one seed).
  DivisionReport step(Tissue& t, GeometryCache& geometry, Rng& rng);
  /// Divides one cell with the rule (and retries); throws GeometryError if
  /// every attempt fails.
  DivisionRecord divide(Tissue& t, CellId c) { return divide(t, c, rng_); }
  DivisionRecord divide(Tissue& t, CellId c, Rng& rng);

  const SizeThreshold& trigger() const { return trigger_; }
  const DivisionRule& rule() const { return *rule_; }
  Rng& rng() { return rng_; }

 private:
  // A 2D step: every plan made on the tissue as it is, then Tissue::splitCells.
  void divideAll(Tissue& t, const std::vector<CellId>& due, Rng& rng, DivisionReport& report);
  // The plan of divide()'s attempts for one cell: the number of attempts, or
  // 0 (and the message) when every one failed.
  int planDivision(const Tissue& t, CellId c, const Plane& base, CellSplitPlan2D& plan, std::string& error) const;

  SizeThreshold trigger_;
  std::shared_ptr<const DivisionRule> rule_;
  DivisionOptions options_;
  Rng rng_;
};

}  // namespace tessella::growth
