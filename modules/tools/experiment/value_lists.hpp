// The strict parsing of an experiment file's attribute values: word lists,
// integers and seed ranges ("1-20 25"). Each returns nullopt for text that is
// not entirely what it should be.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace beft::experiment {

std::vector<std::string> words(const std::string& text);
std::optional<int64_t> parseInteger(const std::string& text);
// "1-20", "3 5 9", "1-3 7": the seeds in order; nullopt for a bad word, a
// descending range, a negative seed or nothing at all.
std::optional<std::vector<uint64_t>> parseSeedList(const std::string& text);

}  // namespace beft::experiment
