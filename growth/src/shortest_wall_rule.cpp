#include "tessella/growth/shortest_wall_rule.hpp"

namespace tessella::growth {

Plane ShortestWallRule::plane(const Tissue& t, CellId c, Rng&) const {
  const NewWallMeasure m(t, c);
  const std::vector<WallCandidate> minima = newWallLocalMinima(m, options_);
  return m.plane(minima.front().normal);  // the global minimum
}

}  // namespace tessella::growth
