#include "tools/experiment/value_lists.hpp"

#include <cerrno>
#include <cstdlib>
#include <sstream>

namespace beft::experiment {

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string word; in >> word;) result.push_back(word);
  return result;
}

std::optional<int64_t> parseInteger(const std::string& text) {
  if (text.empty() || text.find_first_of(" \t\r\n") != std::string::npos) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (errno != 0 || end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

namespace {

// "7" or "1-20" appended to `seeds`; false if it is neither.
bool appendSeeds(const std::string& word, std::vector<uint64_t>& seeds) {
  const auto dash = word.find('-', 1);
  const auto first = parseInteger(word.substr(0, dash));
  const auto last = dash == std::string::npos ? first : parseInteger(word.substr(dash + 1));
  if (!first || !last || *first < 0 || *last < *first) return false;
  for (int64_t seed = *first; seed <= *last; ++seed) seeds.push_back(static_cast<uint64_t>(seed));
  return true;
}

}  // namespace

std::optional<std::vector<uint64_t>> parseSeedList(const std::string& text) {
  std::vector<uint64_t> seeds;
  for (const auto& word : words(text))
    if (!appendSeeds(word, seeds)) return std::nullopt;
  if (seeds.empty()) return std::nullopt;
  return seeds;
}

}  // namespace beft::experiment
