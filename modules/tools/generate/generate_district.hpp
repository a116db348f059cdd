// Generates a district scenario that passes the contract and in which every
// person is reachable: layouts are tried until one passes both checks.
#pragma once

#include <string>

#include "tools/generate/district_layout.hpp"

namespace beft::generate {

struct GeneratedScenario {
  District district;
  std::string xml;
  int attempts = 0;  // layouts tried [-]
};

// Writes the file at `out_path` (whole or not at all) after loading it back
// as every program would and checking reachability; throws with the reason
// when no layout passes in `max_attempts`.
GeneratedScenario generateDistrict(const DistrictParameters& parameters, const std::string& out_path,
                                   const std::string& how_made, int max_attempts = 20);

}  // namespace beft::generate
