#pragma once
// Umbrella header of the tissue module.
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/cell_complex.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/grids.hpp"
#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/properties.hpp"
#include "tessella/tissue/tissue.hpp"
#include "tessella/tissue/validate.hpp"
#include "tessella/tissue/voronoi.hpp"
#include "tessella/tissue/dome.hpp"
