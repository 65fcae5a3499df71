// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/division_scheduler.hpp"

#include <cmath>
#include <cstddef>
#include <exception>
#include <memory>
#include <new>
#include <span>
#include <type_traits>
#include <Eigen/Geometry>

#include "tessella/growth/cell_frame.hpp"
#include "tessella/growth/division_crossings.hpp"
#include "tessella/growth/division_walls.hpp"
#include "tessella/growth/parallel_threshold.hpp"
#include "tessella/tissue/cell_split_plan.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::growth {

namespace {
// Which daughter gets the new lineage id must not hang on the sign an
// eigen-solver happens to give an axis (round-off can flip it, e.g. after a
// restart): the new cell is always on the side the normal's largest
// component points to (+x for a vertical wall, +y for a horizontal one).
Plane withCanonicalSide(Plane plane) {
  Eigen::Index largest = 0;
  plane.normal.cwiseAbs().maxCoeff(&largest);
  if (plane.normal[largest] < 0) plane.normal = -plane.normal;
  return plane;
}

// n default-constructed items, constructed (and destroyed) in parallel: the
// per-cell arrays of a step (tens of MB on a large tissue) are then not
// written, and their pages not first touched, by one thread while the other
// waits. A fixed-size array with std::vector's element access.
template <typename T>
class ParallelArray {
 public:
  explicit ParallelArray(std::size_t n) : data_(std::allocator<T>().allocate(n)), n_(n) {
    const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (m >= kParallelMinItems)
    for (std::ptrdiff_t i = 0; i < m; ++i) ::new (static_cast<void*>(data_ + i)) T();
  }
  ParallelArray(const ParallelArray&) = delete;
  ParallelArray& operator=(const ParallelArray&) = delete;
  ~ParallelArray() {
    const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(n_);
    if constexpr (!std::is_trivially_destructible_v<T>) {
#pragma omp parallel for schedule(static) if (m >= kParallelMinItems)
      for (std::ptrdiff_t i = 0; i < m; ++i) data_[i].~T();
    }
    std::allocator<T>().deallocate(data_, n_);
  }
  T& operator[](std::ptrdiff_t i) { return data_[i]; }
  const T& operator[](std::ptrdiff_t i) const { return data_[i]; }
  std::span<const T> first(std::size_t count) const { return {data_, count}; }
  T* begin() { return data_; }
  T* end() { return data_ + n_; }

 private:
  T* data_;
  std::size_t n_;
};
}  // namespace

DivisionScheduler::DivisionScheduler(SizeThreshold trigger, std::shared_ptr<const DivisionRule> rule,
                                     DivisionOptions options)
    : trigger_(std::move(trigger)), rule_(std::move(rule)), options_(options), rng_(options.seed) {
  if (!rule_) throw InputError("division scheduler: no division rule");
  if (options_.max_attempts < 1)
    throw InputError("division scheduler: max_attempts = " + std::to_string(options_.max_attempts) +
                     " must be >= 1");
}

DivisionRecord DivisionScheduler::divide(Tissue& t, CellId c, Rng& rng) {
  if (options_.tag_walls) divisionWallTags(t);
  const std::int64_t mother = t.lineageId(c);
  // 3D: the rule's planes in its order, each refused when the walls it makes
  // would cross (division_crossings.hpp); 2D: the rule's plane.
  const bool volume = t.dim() == 3;
  const std::vector<Plane> candidates = volume ? rule_->planes(t, c, rng) : std::vector<Plane>{rule_->plane(t, c, rng)};
  const double size = t.dim() == 2 ? std::sqrt(std::abs(cellMeasure(t, c)))
                                   : std::cbrt(std::abs(cellMeasure(t, c)));
  std::string last_error = "rule '" + rule_->name() + "' gave no plane";
  int tried = 0;
  for (const Plane& candidate : candidates) {
    const Plane base = withCanonicalSide(candidate);
    // Perturbations for degenerate cuts: rotate about the cell normal (2D) or
    // an axis perpendicular to the plane normal (3D), and shift along it.
    const Vec3 n0 = base.normal.normalized();
    const Vec3 axis = t.dim() == 2 ? cellFrame(t, c).normal : n0.unitOrthogonal();
    for (int attempt = 0; attempt < options_.max_attempts; ++attempt) {
      ++tried;
      Plane p = base;
      if (attempt > 0) {
        const int k = (attempt + 1) / 2;
        const double sign = attempt % 2 == 1 ? 1.0 : -1.0;
        p.normal = Eigen::AngleAxisd(sign * k * options_.retry_angle, axis) * n0;
        p.point = base.point + sign * k * options_.retry_shift * size * n0;
      }
      try {
        CellSplit split;
        if (volume) {
          // Planned once: checked for crossings, then applied as it is.
          const CellSplitPlan3D plan = planCellSplit3D(t, c, p, options_.split);
          std::string crossing = divisionCrossing(t, c, plan);
          if (!crossing.empty()) {
            last_error = std::move(crossing);
            continue;
          }
          split = t.splitCell(plan);
        } else {
          split = t.splitCell(c, p, options_.split);
        }
        if (options_.tag_walls) divisionWallTags(t)[split.wall] = mother;
        return DivisionRecord{mother, c, split.daughter, split.wall, tried};
      } catch (const GeometryError& e) {
        last_error = e.what();
      }
    }
  }
  const std::string planes =
      candidates.size() > 1 ? " (" + std::to_string(candidates.size()) + " planes of the rule, " +
                                  std::to_string(options_.max_attempts) + " attempts each)"
                            : "";
  throw GeometryError("cell " + std::to_string(c.index()) + " (lineage id " +
                          std::to_string(mother) + ") could not be divided by rule '" +
                          rule_->name() + "' in " + std::to_string(tried) + " attempts" + planes + ": " + last_error,
                      ElementId{t.dim(), c.index()});
}

DivisionReport DivisionScheduler::step(Tissue& t, GeometryCache& geometry, Rng& rng) {
  DivisionReport report;
  const std::vector<CellId> due = trigger_.cellsDue(t, geometry.require(t, kCellMeasures), rng);
  if (t.dim() == 2) {
    divideAll(t, due, rng, report);
  } else {
    for (CellId c : due) {
      if (options_.gate && !options_.gate(t, c)) continue;
      try {
        report.divided.push_back(divide(t, c, rng));
      } catch (const GeometryError& e) {
        report.skipped.push_back(SkippedDivision{c, t.lineageId(c), e.what()});
      }
    }
  }
  // New cells (daughters) draw their noisy thresholds now, so they are set
  // before any caller reads them.
  if (!report.divided.empty()) trigger_.prepare(t, rng);
  return report;
}

void DivisionScheduler::divideAll(Tissue& t, const std::vector<CellId>& due, Rng& rng, DivisionReport& report) {
  std::vector<CellId> cells;
  if (options_.gate) {
    cells.reserve(due.size());
    for (CellId c : due)
      if (options_.gate(t, c)) cells.push_back(c);
  } else {
    cells = due;
  }
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(cells.size());
  if (n == 0) return;
  // Everything is decided on the tissue as it is: the rule's planes (in
  // parallel when the rule allows it, else in the order of the cells, so the
  // random stream is drawn as always), then each cell's plan with its
  // retries. A GeometryError skips the cell; any other error stops the step
  // (the first in cell order), before the tissue changes.
  ParallelArray<Plane> planes(cells.size());
  ParallelArray<std::string> errors(cells.size());
  ParallelArray<std::exception_ptr> failures(cells.size());
  auto findPlane = [&](std::ptrdiff_t i) {
    try {
      planes[i] = withCanonicalSide(rule_->plane(t, cells[i], rng));
    } catch (const GeometryError& e) {
      errors[i] = e.what();
    } catch (...) {
      failures[i] = std::current_exception();
    }
  };
  if (rule_->concurrent()) {
#pragma omp parallel for schedule(dynamic, 64) if (n >= kParallelMinItems)
    for (std::ptrdiff_t i = 0; i < n; ++i) findPlane(i);
  } else {
    for (std::ptrdiff_t i = 0; i < n; ++i) findPlane(i);
  }
  ParallelArray<CellSplitPlan2D> plans(cells.size());
  ParallelArray<int> attempts(cells.size());
#pragma omp parallel for schedule(dynamic, 64) if (n >= kParallelMinItems)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (failures[i] || !errors[i].empty()) continue;
    try {
      attempts[i] = planDivision(t, cells[i], planes[i], plans[i], errors[i]);
    } catch (...) {
      failures[i] = std::current_exception();
    }
  }
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);

  // The cells that divide, in order (the plans of skipped cells dropped; rare:
  // then the kept plans are moved, serially, in order).
  std::size_t kept = 0;
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (attempts[i] == 0) {
      report.skipped.push_back(SkippedDivision{cells[i], t.lineageId(cells[i]), errors[i]});
      continue;
    }
    if (kept != static_cast<std::size_t>(i)) {
      plans[kept] = std::move(plans[i]);
      cells[kept] = cells[i];
      attempts[kept] = attempts[i];
    }
    ++kept;
  }
  const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(kept);
  ParallelArray<std::int64_t> mothers(kept);
#pragma omp parallel for schedule(static) if (m >= kParallelMinItems)
  for (std::ptrdiff_t k = 0; k < m; ++k) mothers[k] = t.lineageId(cells[k]);
  if (options_.tag_walls) divisionWallTags(t);
  std::vector<CellSplit> splits = t.splitCells(plans.first(kept));
  const std::size_t base = report.divided.size();
  report.divided.resize(base + kept);
  PropertyColumn<std::int64_t>* tags = options_.tag_walls ? &divisionWallTags(t) : nullptr;
#pragma omp parallel for schedule(static) if (m >= kParallelMinItems)
  for (std::ptrdiff_t k = 0; k < m; ++k) {
    report.divided[base + k] = DivisionRecord{mothers[k], cells[k], splits[k].daughter, splits[k].wall, attempts[k]};
    if (tags) (*tags)[splits[k].wall] = mothers[k];
    // Freed in parallel here, not one by one when `splits` goes (for large
    // batches by the thread that allocated it: splitCells' loop has the same
    // static shares).
    std::vector<VertexId>().swap(splits[k].new_vertices);
  }
}

int DivisionScheduler::planDivision(const Tissue& t, CellId c, const Plane& base, CellSplitPlan2D& plan,
                                    std::string& error) const {
  // The retries of divide(), planned without changing the tissue.
  const Vec3 n0 = base.normal.normalized();
  Vec3 axis = Vec3::Zero();
  double size = 0;
  std::string last_error;
  for (int attempt = 0; attempt < options_.max_attempts; ++attempt) {
    Plane p = base;
    if (attempt > 0) {
      if (attempt == 1) {
        axis = cellFrame(t, c).normal;
        size = std::sqrt(std::abs(cellMeasure(t, c)));
      }
      const int k = (attempt + 1) / 2;
      const double sign = attempt % 2 == 1 ? 1.0 : -1.0;
      p.normal = Eigen::AngleAxisd(sign * k * options_.retry_angle, axis) * n0;
      p.point = base.point + sign * k * options_.retry_shift * size * n0;
    }
    try {
      plan = planCellSplit2D(t, c, p, options_.split);
      return attempt + 1;
    } catch (const GeometryError& e) {
      last_error = e.what();
    }
  }
  error = "cell " + std::to_string(c.index()) + " (lineage id " + std::to_string(t.lineageId(c)) +
          ") could not be divided by rule '" + rule_->name() + "' in " + std::to_string(options_.max_attempts) +
          " attempts: " + last_error;
  return 0;
}

}  // namespace tessella::growth
