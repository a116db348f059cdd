// Scenario look-ups and the refusal type declared in scenario.hpp.
#include "lib/scenario/scenario.hpp"

namespace beft::scenario {

namespace {
std::string formatLocation(const std::string& file, int line, const std::string& message) {
  // Line 0 means the whole file (it could not be opened, or is empty).
  if (line > 0) return file + ":" + std::to_string(line) + ": " + message;
  return file + ": " + message;
}
}  // namespace

ScenarioError::ScenarioError(std::string file, int line, const std::string& message)
    : std::runtime_error(formatLocation(file, line, message)),
      file_(std::move(file)),
      line_(line),
      message_(message) {}

const Object* Scenario::findObject(const std::string& id) const {
  for (const Object& object : objects) {
    if (object.id == id) return &object;
  }
  return nullptr;
}

double Scenario::congruencyOf(const std::string& label, const std::string& activity,
                              double default_value) const {
  auto found = congruency.find({label, activity});
  return found == congruency.end() ? default_value : found->second;
}

}  // namespace beft::scenario
