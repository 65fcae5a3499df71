#include "tessella/growth/division_rule_factory.hpp"

#include "tessella/growth/besson_dumais_rule.hpp"
#include "tessella/growth/fixed_direction_rule.hpp"
#include "tessella/growth/main_axis_rule.hpp"
#include "tessella/growth/perpendicular_wall_rule.hpp"
#include "tessella/growth/random_direction_rule.hpp"
#include "tessella/growth/shortest_wall_rule.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::growth {

std::vector<std::string> divisionRuleNames() {
  return {"main_axis", "shortest_wall", "perpendicular_to_mother_wall", "random", "fixed",
          "besson_dumais"};
}

std::shared_ptr<const DivisionRule> makeDivisionRule(const std::string& name,
                                                     const DivisionRuleParams& params) {
  if (name == "main_axis") return std::make_shared<MainAxisRule>();
  if (name == "shortest_wall") return std::make_shared<ShortestWallRule>();
  if (name == "perpendicular_to_mother_wall")
    return std::make_shared<PerpendicularWallRule>(params.junction_tolerance);
  if (name == "random") return std::make_shared<RandomDirectionRule>();
  if (name == "fixed") return std::make_shared<FixedDirectionRule>(params.fixed_normal);
  if (name == "besson_dumais") return std::make_shared<BessonDumaisRule>(params.beta);
  std::string known;
  for (const auto& n : divisionRuleNames()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("unknown division rule '" + name + "' (known: " + known + ")");
}

}  // namespace tessella::growth
