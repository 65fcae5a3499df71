#pragma once
// Division rules by configuration name, for config readers:
//   main_axis | shortest_wall | perpendicular_to_mother_wall | random |
//   fixed | besson_dumais

#include <memory>
#include <string>
#include <vector>

#include "tessella/growth/division_rule.hpp"

namespace tessella::growth {

struct DivisionRuleParams {
  Vec3 fixed_normal = Vec3::UnitX();  ///< fixed
  double beta = 10.0;                 ///< besson_dumais
  double junction_tolerance = 0.05;   ///< perpendicular_to_mother_wall
};

/// InputError naming the value and listing the known names for an unknown rule.
std::shared_ptr<const DivisionRule> makeDivisionRule(const std::string& name,
                                                     const DivisionRuleParams& params = {});
std::vector<std::string> divisionRuleNames();

}  // namespace tessella::growth
