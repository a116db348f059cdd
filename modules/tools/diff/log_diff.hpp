// What beft-diff does once its command line is read: read both logs, compare
// their data messages, print the differences, and say how it ended.
#pragma once

#include <cstdio>
#include <set>
#include <string>

namespace beft::diff {

struct DiffOptions {
  std::string first_path, second_path;
  std::set<std::string> channels;  // only these (empty: every data channel)
  bool all = false;                // every difference, not only the first
};

// Exit codes of beft-diff.
constexpr int kIdentical = 0;
constexpr int kDifferent = 1;
constexpr int kBadInput = 2;

// Prints the result on `out` and problems with the input on `err`.
int diffLogs(const DiffOptions& options, std::FILE* out, std::FILE* err);

}  // namespace beft::diff
