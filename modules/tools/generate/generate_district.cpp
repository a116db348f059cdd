#include "tools/generate/generate_district.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "tools/generate/district_xml.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/scenario/reachability.hpp"
#include "lib/scenario/sight_lines.hpp"
#include "lib/common/whole_file.hpp"

namespace beft::generate {

GeneratedScenario generateDistrict(const DistrictParameters& parameters, const std::string& out_path,
                                   const std::string& how_made, int max_attempts) {
  const std::string name = std::filesystem::path(out_path).stem().string();
  const std::string partial = partialPathFor(out_path);
  std::string last_problem;
  for (int attempt = 0; attempt < max_attempts; ++attempt) {
    GeneratedScenario result{layDistrict(parameters, attempt), "", attempt + 1};
    result.xml = districtXml(result.district, name, how_made);
    writeWholeFile(partial, result.xml);
    // Loaded back from beside the output, so sound paths resolve as they will.
    const scenario::Scenario loaded = scenario::loadScenario(partial);
    const auto unreachable = scenario::unreachablePersons(loaded);
    const auto unseeable = unreachable.empty() ? scenario::unseeableObjects(loaded) : std::vector<std::string>{};
    if (unreachable.empty() && unseeable.empty()) {
      commitPartial(partial, out_path);
      return result;
    }
    last_problem = !unreachable.empty()
                       ? std::to_string(unreachable.size()) + " person(s) unreachable, first " + unreachable.front()
                       : std::to_string(unseeable.size()) + " object(s) no reachable place sees, first " +
                             unseeable.front();
  }
  std::remove(partial.c_str());
  throw std::runtime_error("no layout in " + std::to_string(max_attempts) +
                           " attempts had every person reachable and every object seen from somewhere (" +
                           last_problem + ")");
}

}  // namespace beft::generate
