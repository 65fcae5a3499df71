// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The table of surfaces a curved sheet is kept on while it grows
// (surface_projection.hpp), with the parameters each reads.
#include "tessella/growth/registries.hpp"

namespace tessella::growth {

const Registry<SurfaceFactory>& surfaces() {
  static const Registry<SurfaceFactory> table(
      "surface",
      {{"sphere", "Projection onto the sphere |x - center| = radius.",
        {ParamSpec("center", ParamType::Vec3, "Centre of the sphere.").byDefault(std::vector<double>{0, 0, 0}),
         ParamSpec("radius", ParamType::Float, "Radius of the sphere.").byDefault(1.0).above(0)},
        [](const ParamValues& p, const SurfaceProjection&) {
          return blameParam("radius", [&] { return sphereProjection(p.getVec3("center"), p.getFloat("radius")); });
        }},
       {"paraboloid", "Projection onto the paraboloid z = apex.z - curvature * rho^2.",
        {ParamSpec("apex", ParamType::Vec3, "Summit.").byDefault(std::vector<double>{0, 0, 0}),
         ParamSpec("curvature", ParamType::Float, "Curvature factor.").byDefault(1.0).above(0)},
        [](const ParamValues& p, const SurfaceProjection&) {
          return blameParam("curvature",
                            [&] { return paraboloidProjection(p.getVec3("apex"), p.getFloat("curvature")); });
        }},
       {"dome", "The dome the tissue was generated on (tissue.generator: dome), extended past its base.", {},
        [](const ParamValues&, const SurfaceProjection& tissue_surface) {
          if (!tissue_surface)
            throw InputError(
                "'dome' needs tissue.generator: dome, or a snapshot of a run on a dome (which records it)");
          return tissue_surface;
        }}});
  return table;
}

}  // namespace tessella::growth
