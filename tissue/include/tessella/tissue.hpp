// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Umbrella header of the tissue module. The generators (grids, Voronoi,
// dome) are their own module: tessella/generators.hpp.
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/cell_complex.hpp"
#include "tessella/tissue/dome_surface.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/properties.hpp"
#include "tessella/tissue/tissue.hpp"
#include "tessella/tissue/validate.hpp"
