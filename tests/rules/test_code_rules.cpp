// The source tree keeps the measurable code rules (code_rules.hpp), and the
// measure finds what breaks them: planted sources with one long function,
// one long main, braces hidden in comments and literals, long classes.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/rules/code_rules.hpp"
#include "tests/rules/planted_tree.hpp"

namespace fs = std::filesystem;
using beft::rules::describe;
using beft::rules::FunctionSpan;
using beft::rules::functionsIn;
using beft::rules::overlongFunctions;

namespace {

// `count` statement lines, one per line.
std::string statements(int count) {
  std::string text;
  for (int i = 0; i < count; ++i) text += "  total += " + std::to_string(i) + ";\n";
  return text;
}

// A function of exactly `lines` lines: signature, body, closing brace.
std::string functionOfLines(const std::string& signature, int lines) {
  return signature + " {\n  int total = 0;\n" + statements(lines - 4) + "  return total;\n}\n";
}


}  // namespace

using beft::rules::PlantedTree;

TEST(CodeRules, TheSourceTreeHasNoOverlongFunction) {
  const auto overlong = overlongFunctions(BEFT_SOURCE_DIR);
  for (const auto& function : overlong) ADD_FAILURE() << describe(function);
  EXPECT_TRUE(overlong.empty());
}

TEST(CodeRules, TheMeasureFindsTheFunctionsOfTheTree) {
  // Guards the test above against a scan that finds nothing.
  const auto functions = beft::rules::functionsOfTree(BEFT_SOURCE_DIR);
  EXPECT_GT(functions.size(), 500u);
}

TEST(CodeRules, AFunctionOf81LinesAndAMainOf41AreReportedWithFileAndLine) {
  PlantedTree tree;
  tree.write("modules/lib/thing/long.cpp", "#include <cstdio>\n\nnamespace beft {\n\n" +
                                               functionOfLines("int exactlyLimit()", 80) +
                                               functionOfLines("int oneTooMany()", 81) + "}  // namespace beft\n");
  tree.write("modules/tools/thing/main.cpp",
             functionOfLines("int helper()", 60) + functionOfLines("int main(int argc, char** argv)", 41));
  tree.write("planners/fine.cpp", functionOfLines("int main()", 40));
  tree.write("tests/exempt/test_long.cpp", functionOfLines("int veryLong()", 200));
  const auto overlong = overlongFunctions(tree.root());
  ASSERT_EQ(overlong.size(), 2u);
  EXPECT_EQ(describe(overlong[0]), "modules/lib/thing/long.cpp:85: oneTooMany (81 lines)");
  EXPECT_EQ(describe(overlong[1]), "modules/tools/thing/main.cpp:61: main (41 lines)");
}

TEST(CodeRules, BracesInCommentsStringsAndRawStringsAreNotCode) {
  const std::string source =
      "// a comment { with a brace\n"
      "/* a block comment }\n   over two lines { */\n"
      "#define OPEN {\n"
      "const char* kText = \"}}} \\\" {\";\n"
      "const char* kRaw = R\"json({\"a\": \"}\"})json\";\n"
      "const char kBrace = '}';\n"
      "const long kBig = 1'000'000;\n"
      "int f() {\n"
      "  const char* s = \"{\";  // }\n"
      "  return s[0] == '{' ? 1 : 0;\n"
      "}\n"
      "int g() { return 2; }\n";
  const auto functions = functionsIn(source);
  ASSERT_EQ(functions.size(), 2u);
  EXPECT_EQ(functions[0].name, "f");
  EXPECT_EQ(functions[0].first_line, 9);
  EXPECT_EQ(functions[0].last_line, 12);
  EXPECT_EQ(functions[1].name, "g");
  EXPECT_EQ(functions[1].lines(), 1);
}

TEST(CodeRules, ALongClassOrNamespaceIsNotAFunction) {
  std::string members;
  for (int i = 0; i < 100; ++i) members += "  int member" + std::to_string(i) + " = " + std::to_string(i) + ";\n";
  std::string table;
  for (int i = 0; i < 100; ++i) table += "    {" + std::to_string(i) + ", " + std::to_string(i) + "},\n";
  const std::string source = "namespace beft::deep {\nnamespace {\n"
                             "struct Big {\n" + members + "  int get() const { return member0; }\n};\n"
                             "template <typename T>\nclass Holder final : public Base<decltype(T{})> {\n public:\n" +
                             members + "  explicit Holder(int x) : member0(x), member1{x} {}\n};\n"
                             "enum class Colour : int {\n  kRed,\n  kGreen,\n};\n"
                             "const std::map<int, int> kTable = {\n" + table + "};\n"
                             "}  // namespace\n}  // namespace beft::deep\n";
  const auto functions = functionsIn(source);
  ASSERT_EQ(functions.size(), 2u);
  EXPECT_EQ(functions[0].name, "get");
  EXPECT_EQ(functions[0].lines(), 1);
  EXPECT_EQ(functions[1].name, "Holder");
  EXPECT_EQ(functions[1].lines(), 1);
}

TEST(CodeRules, LambdasAndLocalClassesCountTowardTheirFunction) {
  const std::string source =
      "void outer() {\n"
      "  auto inner = [](int x) {\n"
      "    return x;\n"
      "  };\n"
      "  struct Local { int f() { return 1; } };\n"
      "}\n"
      "Foo::Foo(int a) : x_(a), y_{a}, run_([this] { go(); }) {\n"
      "}\n"
      "auto Foo::bar() const noexcept -> int {\n  return 1;\n}\n"
      "bool operator==(const A& a, const A& b) { return a.x == b.x; }\n";
  const auto functions = functionsIn(source);
  ASSERT_EQ(functions.size(), 4u);
  EXPECT_EQ(functions[0].name, "outer");
  EXPECT_EQ(functions[0].lines(), 6);
  EXPECT_EQ(functions[1].name, "Foo::Foo");
  EXPECT_EQ(functions[1].lines(), 2);
  EXPECT_EQ(functions[2].name, "Foo::bar");
  EXPECT_EQ(functions[2].lines(), 3);
  EXPECT_EQ(functions[3].name, "operator==");
}

TEST(CodeRules, ViolationsNameFileLineFunctionAndLength) {
  const FunctionSpan span{"modules/lib/x/y.cpp", 12, 100, "Y::z"};
  EXPECT_EQ(describe(span), "modules/lib/x/y.cpp:12: Y::z (89 lines)");
  EXPECT_EQ(beft::rules::lineLimitFor(span), 80);
  EXPECT_EQ(beft::rules::lineLimitFor(FunctionSpan{"a.cpp", 1, 2, "main"}), 40);
}
