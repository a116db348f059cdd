#include "lib/launch/run_parameters.hpp"

#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace beft::launch {

std::string runParametersJson(const LaunchSpec& spec) {
  nlohmann::json all = nlohmann::json::object();
  for (const auto& process : spec.processes) {
    nlohmann::json parameters = nlohmann::json::object();
    for (std::size_t i = 0; i + 1 < process.args.size(); ++i) {
      if (process.args[i] != "--param") continue;
      const std::string& setting = process.args[i + 1];
      const auto eq = setting.find('=');
      if (eq != std::string::npos && eq > 0) parameters[setting.substr(0, eq)] = setting.substr(eq + 1);
    }
    all[process.name] = parameters;
  }
  return all.dump(2) + "\n";
}

bool writeRunParameters(const LaunchSpec& spec, const std::string& path) {
  std::ofstream out(path);
  out << runParametersJson(spec);
  return static_cast<bool>(out);
}

std::map<std::string, std::string> readRunParameters(const std::string& path, const std::string& process) {
  std::ifstream in(path);
  if (!in) return {};
  std::map<std::string, std::string> parameters;
  try {
    const nlohmann::json all = nlohmann::json::parse(in);
    if (!all.is_object()) throw std::runtime_error("not a JSON object");
    const auto found = all.find(process);
    if (found == all.end()) return {};
    if (!found->is_object()) throw std::runtime_error("\"" + process + "\" is not an object");
    for (const auto& [name, value] : found->items()) {
      if (!value.is_string()) throw std::runtime_error("\"" + process + "\"." + name + " is not a string");
      parameters[name] = value.get<std::string>();
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a run's parameters file: " + e.what());
  }
  return parameters;
}

}  // namespace beft::launch
