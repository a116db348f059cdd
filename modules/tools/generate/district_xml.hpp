// Writes a generated district as a scenario file (scenario-format.md).
#pragma once

#include <string>

#include "tools/generate/district_layout.hpp"

namespace beft::generate {

// The scenario XML; `how_made` goes into the header comment (the command
// that regenerates the file).
std::string districtXml(const District& district, const std::string& name, const std::string& how_made);

}  // namespace beft::generate
