// The code rules that can be measured: no function body over 80 lines and no
// main() over 40, in the C++ files of modules/, blackboard/ and planners/
// (tests are exempt). Read by test_code_rules.
//
// The measure is a brace-matching scan, not a parser: comments, string and
// character literals, raw strings and preprocessor lines are blanked first;
// then every brace at namespace or class scope is classified as a function
// body, a scope (namespace, class, struct, union, enum, extern "C") or an
// initializer. A function spans from the line its declaration starts on
// (template line included) to the line of its closing brace; lambdas and
// local classes inside it count toward it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace beft::rules {

constexpr int kMaxFunctionLines = 80;
constexpr int kMaxMainLines = 40;

struct FunctionSpan {
  std::string file;  // relative to the repository root (empty for a bare source text)
  int first_line = 0;  // 1-based: where the declaration starts
  int last_line = 0;   // the line of the closing brace
  std::string name;    // as written before the parameter list ("Foo::bar", "TEST", "main")
  int lines() const { return last_line - first_line + 1; }
};

// Every function body of one C++ source text, in order of appearance.
std::vector<FunctionSpan> functionsIn(const std::string& source);

// The most lines a function of this name may span.
int lineLimitFor(const FunctionSpan& function);

// Every function of the C++ files under modules/, blackboard/ and planners/
// of a repository, and those that break the limits.
std::vector<FunctionSpan> functionsOfTree(const std::filesystem::path& repository_root);
std::vector<FunctionSpan> overlongFunctions(const std::filesystem::path& repository_root);

std::string describe(const FunctionSpan& function);  // "file:line: name (N lines)"

}  // namespace beft::rules
