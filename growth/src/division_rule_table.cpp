// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The table of division rules. Each rule's source defines its entry (name,
// doc, parameters, factory); a new rule is its source, its declaration below
// and its line in the list, in the order docs and choices list them.
// (A table rather than self-registering objects: a static library drops the
// objects nobody references.)
#include "tessella/growth/registries.hpp"

namespace tessella::growth {

DivisionRuleEntry mainAxisRuleEntry();
DivisionRuleEntry shortestWallRuleEntry();
DivisionRuleEntry perpendicularWallRuleEntry();
DivisionRuleEntry randomDirectionRuleEntry();
DivisionRuleEntry fixedDirectionRuleEntry();
DivisionRuleEntry bessonDumaisRuleEntry();
DivisionRuleEntry fixedAngleToMainAxisRuleEntry();

const Registry<DivisionRuleFactory>& divisionRules() {
  static const Registry<DivisionRuleFactory> table("division rule", {
      mainAxisRuleEntry(),
      shortestWallRuleEntry(),
      perpendicularWallRuleEntry(),
      randomDirectionRuleEntry(),
      fixedDirectionRuleEntry(),
      bessonDumaisRuleEntry(),
      fixedAngleToMainAxisRuleEntry(),
  });
  return table;
}

std::shared_ptr<const DivisionRule> makeDivisionRule(const std::string& name, const ParamValues& params) {
  return divisionRules().make(name, params);
}

std::vector<std::string> divisionRuleNames() { return divisionRules().names(); }

}  // namespace tessella::growth
