// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// A shoot apical meristem in C++ with Tessella's public API only.
//
// The L1 layer is a Voronoi tissue lifted onto a spherical-cap dome. A
// meristem velocity field makes a slowly growing central zone around the
// summit and a fast periphery; a projection keeps every vertex on the dome,
// so cells flow from the summit down the flanks. Each step every cell's
// identity is recomputed from its distance to the summit (central zone or
// periphery), cells above a size threshold divide across their main axis,
// and a ParaView series records every property.
//
//   meristem [output-directory]      (default: meristem_out)
#include <cstdio>
#include <memory>
#include <string>

#include <tessella/generators.hpp>
#include <tessella/growth/growth.hpp>
#include <tessella/io/series.hpp>
#include <tessella/tissue.hpp>

using namespace tessella;

namespace {

// The model's parameters, in the dome's length unit and time unit.
struct Model {
  Dome dome{Dome::Shape::SphericalCap, /*base_radius=*/5.0, /*height=*/2.5};
  std::size_t initial_cells = 80;
  double central_radius = 1.5;   // central zone: distance to the summit below this
  double central_rate = 0.02;    // relative growth rate of the central zone
  double peripheral_rate = 0.15; // ... and of the periphery
  double division_area = 1.6;    // mean cell area at division
  double division_noise = 0.15;  // its standard deviation between cells
  double dt = 0.1, end = 6.0;
  int output_every = 5;          // steps between snapshots
};

enum Zone : int { Central = 0, Peripheral = 1 };

}  // namespace

int main(int argc, char** argv) {
  const std::string out_dir = argc > 1 ? argv[1] : "meristem_out";
  const Model m;
  try {
    // --- the tissue: Voronoi cells of the footprint disk, lifted onto the dome
    const Disk footprint{m.dome.base_center, m.dome.base_radius};
    const auto seeds = randomSeeds(footprint, m.initial_cells, /*rng_seed=*/7);
    Tissue t = domeTissue(seeds, m.dome, VoronoiOptions{.lloyd_iterations = 2});
    const Vec3 summit = m.dome.base_center + Vec3(0, 0, m.dome.height);

    // --- cell properties, each with the policy division applies to it
    // Identity is recomputed every step, so what daughters inherit only
    // matters between the division and the next update: they keep the mother's.
    auto& zone = t.cellProperties().add<int>("zone", Peripheral, DivisionPolicy::Copy);
    auto& distance = t.cellProperties().add<double>("summit_distance", 0.0, DivisionPolicy::Copy);
    // The founder cell each cell descends from: clonal sectors in ParaView.
    auto& clone = t.cellProperties().add<std::int64_t>("clone", -1, DivisionPolicy::Copy);
    for (CellId c : t.cells()) clone[c] = t.lineageId(c);

    auto updateIdentity = [&] {
      std::size_t central = 0;
      for (CellId c : t.cells()) {
        distance[c] = (cellCentroid(t, c) - summit).norm();
        zone[c] = distance[c] < m.central_radius ? Central : Peripheral;
        central += zone[c] == Central;
      }
      return central;
    };

    // --- growth: slow centre, fast periphery, vertices kept on the dome
    growth::MeristemFieldParams field;
    field.apex = summit;
    field.axis = Vec3::UnitZ();
    field.central_radius = m.central_radius;
    field.transition_width = 0.3;
    field.central_rate = m.central_rate;
    field.peripheral_rate = m.peripheral_rate;
    growth::GrowthOptions options;
    options.projection = growth::domeProjection(m.dome);
    growth::GrowthIntegrator integrator(std::make_shared<growth::MeristemField>(field), options);

    // --- division: noisy size threshold, plane across the main axis
    growth::DivisionScheduler divide(growth::SizeThreshold::noisy(m.division_area, m.division_noise),
                                     std::make_shared<growth::MainAxisRule>());

    io::SeriesWriter series(out_dir, "meristem");
    std::size_t central = updateIdentity();
    series.write(t, t.time());
    std::printf("%6s %6s %8s %9s %10s %9s\n", "time", "cells", "central", "divisions", "area", "snapshot");
    std::printf("%6.2f %6zu %8zu %9d %10.4f %9zu\n", t.time(), t.numCells(), central, 0, totalMeasure(t),
                series.steps());

    const int steps = static_cast<int>(m.end / m.dt + 0.5);
    std::size_t divisions = 0, skipped = 0;
    GeometryCache geometry;  // shared: division and snapshots read the areas the growth step computed
    for (int step = 1; step <= steps; ++step) {
      integrator.step(t, m.dt, geometry);
      const growth::DivisionReport report = divide.step(t, geometry);
      divisions += report.divided.size();
      skipped += report.skipped.size();
      central = updateIdentity();
      if (step % m.output_every == 0 || step == steps) {
        // The invariants of the complex, checked before anything is written.
        validateOrThrow(t);
        series.write(t, t.time(), {}, &geometry);
        std::printf("%6.2f %6zu %8zu %9zu %10.4f %9zu\n", t.time(), t.numCells(), central, divisions,
                    totalMeasure(t), series.steps());
      }
    }
    std::printf("%zu divisions (%zu postponed), series: %s\n", divisions, skipped, series.pvdPath().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "meristem: %s\n", e.what());
    return 1;
  }
  return 0;
}
