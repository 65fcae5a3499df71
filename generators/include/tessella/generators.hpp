#pragma once
// Umbrella header of the generators module: the tissues a model starts from.
#include "tessella/generators/dome.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"
