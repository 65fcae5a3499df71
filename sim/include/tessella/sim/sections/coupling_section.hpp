// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The solver sections: `diffusion:` (one or several diffusing species on the
// tissue's finite-element mesh, with reaction terms), `compartments:` (one well-mixed concentration per
// cell, exchanged across walls, with polar transport) and `elasticity:`
// (linear elasticity of the tissue with boundary conditions on its faces).
// Each is off by default and read into the parameters of the stage that
// solves it (coupling_stages.hpp). See docs/solvers.md ("Coupling").
//
// Values written as "name=value, name=value" strings (per-cell-type
// coefficients, boundary conditions per region) are checked when the config
// is read, so a bad item is a ConfigError at its key.

#include "tessella/sim/config/config.hpp"
#include "tessella/sim/config/schema.hpp"
#include "tessella/sim/sections/section_unit.hpp"
#include "tessella/sim/stages/coupling_stages.hpp"

namespace tessella::sim {

void declareDiffusionSection(Schema& schema);
void declareCompartmentSection(Schema& schema);
void declareElasticitySection(Schema& schema);
DiffusionSpec readDiffusionSection(const Config& config);
CompartmentSpec readCompartmentSection(const Config& config);
ElasticitySpec readElasticitySection(const Config& config);
/// Each section's stage when the section is on; diffusion and elasticity
/// share the StageList's FieldMesh.
void addDiffusionStage(const DiffusionSpec& diffusion, StageList& stages);
void addCompartmentStage(const CompartmentSpec& compartments, StageList& stages);
void addElasticityStage(const ElasticitySpec& elasticity, StageList& stages);

}  // namespace tessella::sim
