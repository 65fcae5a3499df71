// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Umbrella header of the generators module: the tissues a model starts from.
#include "tessella/generators/dome.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"
