// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The `tissue:` section: which generator builds the initial tissue, and its
// parameters. `tissue.generator` picks one of the subsections; only that one
// is read (and written to run.yaml). The choices are the generators of
// tessella::generators() (generators/generator_registry.hpp: grids, Voronoi,
// dome), whose parameter tables are the subsections' keys, and two sources
// read through io, listed in tissueFileSources():
//
//   snapshot          a .vtu written by Tessella: a run restarts from it
//   import            a segmented tissue from another tool (io::importFormats())

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include "tessella/generators/generator_registry.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/tissue/dome_surface.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::sim {

/// A generator of tessella::generators() and its parameters, as read from
/// tissue.<name> (completed with the defaults and checked).
struct GeneratorSpec {
  std::string name;
  ParamValues params;
  /// What it will make (the generator's shape() of these parameters).
  GeneratedShape shape() const;
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

using TissueSpec = std::variant<GeneratorSpec, SnapshotSpec, ImportSpec>;

/// The sources of tissue.generator sim adds to the generators' table: they
/// read a file through io (snapshot, import). Each reads its completed
/// parameters into its spec; an InputError is located at tissue.<name>.file.
using FileSourceReader = std::function<TissueSpec(const ParamValues&)>;
const Registry<FileSourceReader>& tissueFileSources();

/// The dome a tissue spec puts its sheet on: a generator's (its dome() hook,
/// the dome generator), or the one saved in a snapshot of a run on a dome
/// (domeRunState); none otherwise.
std::optional<Dome> tissueDome(const TissueSpec& spec);
/// A dome as run-state entries (dome.*), exact to the bit.
io::RunState domeRunState(const Dome& dome);

/// Declares tissue.* in the schema.
void declareTissueSection(Schema& schema);

/// The generator `name` with the values tissue.<name> gives (defaults for the
/// rest), without the checks across keys: also for a section that is given
/// but not chosen.
GeneratorSpec describedGenerator(const Config& config, const std::string& name);

/// Reads tissue.* from a validated config, with the checks that involve
/// several keys (min < max, count vs seed_file, ...), as ConfigErrors.
TissueSpec readTissueSection(const Config& config);

/// Builds the tissue a spec describes; `rng_seed` draws random seed points.
/// Generator errors (a malformed seed file, a seed outside the domain) are
/// InputErrors from generators/.
Tissue buildTissue(const TissueSpec& spec, std::uint64_t rng_seed);

/// buildTissue() for a spec read from `config`: generator InputErrors are
/// re-raised as ConfigErrors located at the key that caused them.
Tissue buildTissue(const TissueSpec& spec, std::uint64_t rng_seed, const Config& config);

}  // namespace tessella::sim
