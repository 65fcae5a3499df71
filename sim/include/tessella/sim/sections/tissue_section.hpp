#pragma once
// The `tissue:` section: which generator builds the initial tissue, and its
// parameters. `tissue.generator` picks one of the subsections; only that one
// is read (and written to run.yaml).
//
//   rectangular_grid  nx x ny rectangles                     (2D)
//   hexagonal_grid    nx x ny regular hexagons               (2D)
//   box_grid          nx x ny x nz boxes                     (3D)
//   voronoi           Voronoi cells of seed points clipped to a rectangle or
//                     disk (2D) or to a box or ball (3D)
//   dome              Voronoi cells of a disk lifted onto a dome (curved 2D
//                     sheet, the L1 layer of a shoot apical meristem)
//   snapshot          a .vtu written by Tessella: a run restarts from it
//   import            a segmented tissue from another tool (io::importFormats())

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include "tessella/generators/dome.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::sim {

struct RectangularGridSpec {
  std::size_t nx = 10, ny = 10;
  double dx = 1.0, dy = 1.0;
  Vec3 origin = Vec3::Zero();
};

struct HexagonalGridSpec {
  std::size_t nx = 10, ny = 10;
  double radius = 1.0;
  Vec3 origin = Vec3::Zero();
};

struct BoxGridSpec {
  std::size_t nx = 4, ny = 4, nz = 4;
  double dx = 1.0, dy = 1.0, dz = 1.0;
  Vec3 origin = Vec3::Zero();
};

/// Where the seed points of a Voronoi or dome tissue come from: `count`
/// uniform random points (drawn with the run's RNG seed), or a CSV file.
struct SeedSpec {
  std::size_t count = 0;
  std::string file;  ///< absolute path; empty for random seeds
  VoronoiOptions options;
};

struct VoronoiSpec {
  std::variant<Rectangle, Disk, Box, Ball> domain;
  SeedSpec seeds;
  int dim() const { return domain.index() < 2 ? 2 : 3; }
};

struct DomeSpec {
  Dome dome;
  SeedSpec seeds;
};

/// A saved snapshot to restart from. It is read while the configuration is
/// read (its dimension and time decide other keys), so the tissue is kept.
struct SnapshotSpec {
  std::string file;  ///< absolute path
  std::shared_ptr<const Tissue> tissue;
  /// The run state saved with the tissue (empty for snapshots without one).
  io::RunState state;
  /// The random stream the restarted run continues ("" for a fresh stream),
  /// decided by readSimulationConfig (continueRunState).
  std::string rng_state;
};

/// A segmented tissue imported from another tool's file (io::importTissue),
/// read when the tissue is built.
struct ImportSpec {
  std::string file;  ///< absolute path
  io::ImportOptions options;
  /// Read when the config is read (as a snapshot is), so that a bad file and
  /// every check against the tissue's dimension come before any output.
  std::shared_ptr<const Tissue> tissue;
};

using TissueSpec = std::variant<RectangularGridSpec, HexagonalGridSpec, BoxGridSpec, VoronoiSpec, DomeSpec,
                                SnapshotSpec, ImportSpec>;

/// The dome a tissue spec puts its sheet on: a dome generator's, or the one
/// saved in a snapshot of a run on a dome (domeRunState); none otherwise.
std::optional<Dome> tissueDome(const TissueSpec& spec);
/// A dome as run-state entries (dome.*), exact to the bit.
io::RunState domeRunState(const Dome& dome);

/// Declares tissue.* in the schema.
void declareTissueSection(Schema& schema);

/// Reads tissue.* from a validated config, with the checks that involve
/// several keys (min < max, count vs seed_file, ...), as ConfigErrors.
TissueSpec readTissueSection(const Config& config);

/// Builds the tissue a spec describes; `rng_seed` draws random seed points.
/// Generator errors (a malformed seed file, a seed outside the domain) are
/// InputErrors from tissue/.
Tissue buildTissue(const TissueSpec& spec, std::uint64_t rng_seed);

/// buildTissue() for a spec read from `config`: generator InputErrors are
/// re-raised as ConfigErrors located at the key that caused them.
Tissue buildTissue(const TissueSpec& spec, std::uint64_t rng_seed, const Config& config);

}  // namespace tessella::sim
