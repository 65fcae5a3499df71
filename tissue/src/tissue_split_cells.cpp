// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Tissue::splitCells: many 2D cells divided at once by plans made on the
// tissue as it is. The plans become chords of CellComplex::splitFaces (which
// numbers and builds everything in parallel); positions, property divisions
// and lineage follow in parallel, each element written by one thread.

#include <algorithm>
#include <cmath>
#include <string>

#include "tessella/tissue/cell_split_plan.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/tissue.hpp"
#include "tessella/tissue/uninitialized_vector.hpp"
#include "parallel_claims.hpp"

namespace tessella {

namespace {

constexpr std::ptrdiff_t kParallelMin = 1024;

bool hasCustomColumn(const PropertyStore& store) {
  for (std::size_t i = 0; i < store.numColumns(); ++i)
    if (store.column(i).policy() == DivisionPolicy::Custom) return true;
  return false;
}

}  // namespace

std::vector<CellSplit> Tissue::splitCells(std::span<const CellSplitPlan2D> plans) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(plans.size());
  if (dim() != 2) throw InputError("splitCells: the tissue is 3D (it divides the cells of 2D tissues)");
  // Cell -> plan, claimed in parallel; on a dead cell or a cell claimed twice
  // the serial loop runs again to name the first defect in plan order.
  UninitializedVector<std::int32_t> plan_of = filledInParallel<std::int32_t>(cellSlots(), -1);
  if (!detail::claimInParallel(
          n, plan_of, [&](std::ptrdiff_t i) { return plans[i].cell; }, [&](CellId c) { return alive(c); },
          kParallelMin)) {
    std::fill(plan_of.begin(), plan_of.end(), -1);
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const CellId c = plans[i].cell;
      if (!alive(c))
        throw TopologyError("splitCells: plan " + std::to_string(i) + ": cell " + std::to_string(c.index()) +
                                " is not alive", {2, c.index()});
      if (plan_of[c.index()] >= 0)
        throw InputError("splitCells: cell " + std::to_string(c.index()) + " has two plans (" +
                         std::to_string(plan_of[c.index()]) + " and " + std::to_string(i) + ")");
      plan_of[c.index()] = static_cast<std::int32_t>(i);
    }
  }

  // Plans as chords. A new vertex on an edge another plan cuts first is
  // reused when it lies within this plan's snap distance of its plane (as
  // planning after that plan was applied would have snapped to it).
  // (Unwritten until the loop, which writes each chord whole: no serial zeroing.)
  UninitializedVector<FaceChord> chords(plans.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const CellSplitPlan2D& p = plans[i];
    FaceChord& ch = chords[i];
    ch = FaceChord{};
    ch.face = FaceId(p.cell.index());
    ch.new_face_from_0_to_1 = p.daughter_from_a_to_b;
    const CutNode* nodes[2] = {&p.a, &p.b};
    for (int k = 0; k < 2; ++k) {
      const CutNode& x = *nodes[k];
      ChordEnd& end = ch.ends[k];
      if (!x.isNew()) {
        end.vertex = x.vertex;
        continue;
      }
      end.edge = x.edge;
      const Vec3& a = position(complex_.edgeFrom(x.edge));
      const Vec3 ab = position(complex_.edgeTo(x.edge)) - a;
      end.t = (x.point - a).dot(ab) / ab.squaredNorm();
      for (FaceId g : complex_.edgeFaces(x.edge)) {
        const std::int32_t j = g.index() < plan_of.size() ? plan_of[g.index()] : -1;
        if (j < 0 || j >= i) continue;
        for (int kk = 0; kk < 2; ++kk) {
          const CutNode& y = kk == 0 ? plans[j].a : plans[j].b;
          if (y.isNew() && y.edge == x.edge &&
              std::abs(p.plane.normal.dot(y.point - p.plane.point)) <= p.snap_distance)
            end.same_as = 2 * j + kk;
        }
      }
    }
  }
  const UninitializedVector<ChordSplit> splits = complex_.splitFaces(chords);

  growInParallel(positions_, complex_.slots(0));  // every new vertex is placed below
  PropertyStore* stores[] = {&properties_[0], &properties_[1], &properties_[2]};
  const std::size_t sizes[] = {complex_.slots(0), complex_.slots(1), complex_.slots(2)};
  PropertyStore::resizeTogether(stores, sizes);  // as grew(0), grew(1), grew(2), the columns in parallel
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k)
      if (chords[i].ends[k].isNew()) positions_[splits[i].vertex[k].index()] = (k == 0 ? plans[i].a : plans[i].b).point;

  // Edge properties: each edge split as splitEdge would (length fraction at that moment), in order.
  auto divideEdge = [&](const ChordSplit& s, int k) {
    const Vec3& v = positions_[s.vertex[k].index()];
    const double kept = (v - positions_[s.split_from[k].index()]).norm();
    const double part = (positions_[s.split_to[k].index()] - v).norm();
    properties_[1].divide(s.split_edge[k].index(), s.new_edge[k].index(),
                          kept + part > 0 ? kept / (kept + part) : 0.5);
  };
  const bool edges_parallel = n >= kParallelMin && !hasCustomColumn(properties_[1]);
#pragma omp parallel for schedule(static) if (edges_parallel)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) {
      const ChordSplit& s = splits[i];
      if (!s.first_on_edge[k]) continue;
      divideEdge(s, k);
      if (s.next_on_edge[k] >= 0) divideEdge(splits[s.next_on_edge[k] / 2], s.next_on_edge[k] % 2);
    }

  // Cells: properties by the plan's fraction, lineage ids mother then daughter, plan after plan.
  const std::int64_t first_id = next_lineage_;
  const bool cells_parallel = n >= kParallelMin && !hasCustomColumn(properties_[2]);
#pragma omp parallel for schedule(static) if (cells_parallel)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const Index mother = plans[i].cell.index(), daughter = splits[i].face.index();
    const std::int64_t mother_lineage = (*lineage_)[mother];
    properties_[2].divide(mother, daughter, plans[i].mother_fraction);
    (*lineage_)[mother] = first_id + 2 * i;
    (*lineage_)[daughter] = first_id + 2 * i + 1;
    for (Index c : {mother, daughter}) {
      (*parent_)[c] = mother_lineage;
      (*birth_)[c] = time_;
    }
  }
  next_lineage_ = first_id + 2 * n;
  ++geometry_version_;
  paranoidCheck("splitCells");

  std::vector<CellSplit> out(plans.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    out[i].daughter = CellId(splits[i].face.index());
    out[i].wall = WallId(splits[i].chord.index());
    for (int k = 0; k < 2; ++k)
      if (chords[i].ends[k].isNew()) out[i].new_vertices.push_back(splits[i].vertex[k]);
  }
  return out;
}

}  // namespace tessella
