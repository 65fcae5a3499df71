// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The generator table: every generator a configuration (`tissue.generator`)
// or a script (tessella.generate) picks by name, with its doc, the parameters
// it reads (types, defaults, ranges, docs: tessella/tissue/parameters.hpp)
// and its factory. The YAML schema, the config reader, the Python bindings
// and docs/config.md read this table, so a new generator is one entry here
// (docs/extending.md, "Add a generator").
//
//   Tissue t = generators().make("hexagonal_grid", {{"nx", std::int64_t{4}}}, /*rng_seed=*/1);

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tessella/tissue/dome_surface.hpp"
#include "tessella/tissue/registry.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella {

/// What a generator makes, known from its parameters before it runs.
struct GeneratedShape {
  int dim = 2;
  Embedding embedding = Embedding::Planar;
  /// The parameter that decided the shape (voronoi: "domain"); "" when the
  /// generator alone does.
  std::string decided_by;
};

/// A group of parameters named "<name>.<leaf>" that apply only when the Enum
/// parameter `selector` is `name` (a Voronoi domain's size). In YAML, a
/// subsection.
struct ParamGroup {
  std::string name;
  std::string doc;
  std::string selector;
};

/// How the caller spells a parameter in messages: sim passes
/// "tissue.voronoi.<param>", a script the parameter name itself.
using ParamNamer = std::function<std::string(const std::string& param)>;

struct GeneratorFactory {
  /// The tissue; `rng_seed` draws random seed points. An InputError caused by
  /// a file a parameter names (a seed file) is a ParamError at that parameter.
  std::function<Tissue(const ParamValues&, std::uint64_t rng_seed)> build = {};
  std::function<GeneratedShape(const ParamValues&)> shape = {};
  /// Checks across parameters (count and seed_file, min < max, the cell count
  /// limit): a ParamError at the parameter to blame, whose message names the
  /// others as `key` spells them. Empty when there are none.
  std::function<void(const ParamValues&, const ParamNamer& key)> check = {};
  std::vector<ParamGroup> groups = {};
  /// The dome a generated sheet lies on (growth can keep it there); empty
  /// when the generator makes no dome sheet.
  std::function<std::optional<Dome>(const ParamValues&)> dome = {};

  /// check(), then build().
  Tissue operator()(const ParamValues& params, std::uint64_t rng_seed) const;
};

using GeneratorRegistry = Registry<GeneratorFactory>;

/// The generators: rectangular_grid, hexagonal_grid, box_grid, voronoi, dome.
const GeneratorRegistry& generators();

/// More cells than this is refused before anything is allocated (a typo such
/// as nx: 100000 must not exhaust memory before anything is said).
inline constexpr double kMaxGeneratedCells = 1e7;

}  // namespace tessella
