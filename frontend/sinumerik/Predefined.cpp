// The control's predefined names (keywords, procedures, functions, addresses, cycles) from the
// operator table: a call or an address ncc does not simulate is named as what it is, not as a
// missing subprogram (a user subprogram of that name on the search path still wins).
#include "frontend/sinumerik/Parser.h"

#include <algorithm>
#include <cstring>

namespace ncc::sin {

namespace {
const PredefinedName kPredefined[] = {
#include "frontend/sinumerik/Predefined.inc"
};
}  // namespace

const PredefinedName *findPredefined(std::string_view name) {
  auto it = std::lower_bound(std::begin(kPredefined), std::end(kPredefined), name,
                             [](const PredefinedName &p, std::string_view n) { return p.name < n; });
  return it != std::end(kPredefined) && it->name == name ? it : nullptr;
}

}  // namespace ncc::sin
