#include "tools/experiment/episodes.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

namespace beft::experiment {
namespace {

// Only what is safe in a folder name and a shell word; '_' joins the parts.
std::string safe(const std::string& text) {
  std::string result = text;
  for (char& c : result)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '+') c = '_';
  return result;
}

std::string joined(const std::vector<std::pair<std::string, std::string>>& values, bool condition_only) {
  std::string id;
  for (const auto& [factor, value] : values) {
    if (condition_only && (factor == kScene || factor == kSeed)) continue;
    id += (id.empty() ? "" : "_") + idPart(factor, value);
  }
  return id;
}

}  // namespace

std::string idPart(const std::string& factor, const std::string& value) {
  if (factor == kScene) return safe(value);
  if (factor == "net") return "net-" + safe(std::filesystem::path(value).stem().string());
  const std::string name = factor.rfind("set:", 0) == 0 ? factor.substr(4) : factor;
  return safe(name) + "-" + safe(value);
}

const std::string* Episode::value(const std::string& factor) const {
  for (const auto& [name, v] : values)
    if (name == factor) return &v;
  return nullptr;
}

std::string Episode::condition() const {
  const std::string id = joined(values, true);
  return id.empty() ? "all" : id;
}

std::string Episode::pairing() const {
  const std::string* seed = value(kSeed);
  return *value(kScene) + (seed ? "_seed-" + *seed : "");
}

std::vector<Episode> expandEpisodes(const Experiment& experiment) {
  std::vector<Factor> factors = {{kScene, {}}};
  for (const auto& scene : experiment.scenes) factors[0].values.push_back(scene.name);
  factors.insert(factors.end(), experiment.factors.begin(), experiment.factors.end());
  std::vector<Episode> episodes = {Episode{}};
  if (!experiment.listed.empty()) {
    episodes.clear();
    for (const auto& values : experiment.listed) episodes.push_back(Episode{"", values});
    factors.clear();
  }
  for (const auto& factor : factors) {
    std::vector<Episode> longer;
    for (const auto& episode : episodes)
      for (const auto& value : factor.values) {
        longer.push_back(episode);
        longer.back().values.emplace_back(factor.name, value);
      }
    episodes = std::move(longer);
  }
  std::set<std::string> ids;
  for (auto& episode : episodes) {
    episode.id = joined(episode.values, false);
    if (!ids.insert(episode.id).second)
      throw ExperimentError(experiment.file + ": two episodes would share the id '" + episode.id + "'");
  }
  return episodes;
}

}  // namespace beft::experiment
