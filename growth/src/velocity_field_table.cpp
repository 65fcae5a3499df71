// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The table of velocity fields. Each field's source defines its entry (name,
// doc, parameters, factory); a new field is its source, its declaration below
// and its line in the list.
#include "tessella/growth/registries.hpp"

namespace tessella::growth {

VelocityFieldEntry uniformFieldEntry();
VelocityFieldEntry anisotropicFieldEntry();
VelocityFieldEntry radialFieldEntry();
VelocityFieldEntry bumpFieldEntry();
VelocityFieldEntry meristemFieldEntry();
VelocityFieldEntry expressionFieldEntry();

const Registry<VelocityFieldFactory>& velocityFields() {
  static const Registry<VelocityFieldFactory> table("velocity field", {
      uniformFieldEntry(),
      anisotropicFieldEntry(),
      radialFieldEntry(),
      bumpFieldEntry(),
      meristemFieldEntry(),
      expressionFieldEntry(),
  });
  return table;
}

}  // namespace tessella::growth
