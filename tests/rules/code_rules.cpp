#include "tests/rules/code_rules.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace beft::rules {
namespace fs = std::filesystem;

namespace {

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Blanks [from, to) of `code` with spaces, keeping line breaks so that
// positions still map to the same lines.
void blank(std::string& code, size_t from, size_t to) {
  for (size_t i = from; i < to && i < code.size(); ++i) {
    if (code[i] != '\n') code[i] = ' ';
  }
}

// The end (one past the closing quote) of a quoted literal starting at `open`.
size_t endOfQuoted(const std::string& text, size_t open) {
  const char quote = text[open];
  size_t i = open + 1;
  while (i < text.size() && text[i] != quote && text[i] != '\n') i += text[i] == '\\' ? 2 : 1;
  return std::min(i + 1, text.size());
}

// Whether the '"' at `quote` opens a raw string: R, u8R, uR, UR or LR before it.
bool opensRawString(const std::string& text, size_t quote) {
  if (quote == 0 || text[quote - 1] != 'R') return false;
  size_t start = quote - 1;
  while (start > 0 && isIdentifierChar(text[start - 1])) --start;
  const std::string prefix = text.substr(start, quote - start);
  return prefix == "R" || prefix == "u8R" || prefix == "uR" || prefix == "UR" || prefix == "LR";
}

size_t endOfRawString(const std::string& text, size_t quote) {
  const size_t paren = text.find('(', quote);
  if (paren == std::string::npos) return text.size();
  const std::string closing = ")" + text.substr(quote + 1, paren - quote - 1) + "\"";
  const size_t end = text.find(closing, paren);
  return end == std::string::npos ? text.size() : end + closing.size();
}

// Whether the '\'' at `quote` separates digits (1'000'000) rather than
// opening a character literal: the token it sits in starts with a digit.
bool isDigitSeparator(const std::string& text, size_t quote) {
  size_t start = quote;
  while (start > 0 && (isIdentifierChar(text[start - 1]) || text[start - 1] == '\'')) --start;
  return start < quote && std::isdigit(static_cast<unsigned char>(text[start]));
}

// The end of a preprocessor line, following backslash continuations.
size_t endOfDirective(const std::string& text, size_t hash) {
  size_t end = hash;
  while (end < text.size()) {
    end = text.find('\n', end);
    if (end == std::string::npos) return text.size();
    size_t last = end;
    while (last > hash && (text[last - 1] == ' ' || text[last - 1] == '\r')) --last;
    if (last == hash || text[last - 1] != '\\') return end;
    ++end;
  }
  return end;
}

// The source with comments, literals and preprocessor lines blanked.
std::string codeOnly(const std::string& source) {
  std::string code = source;
  bool line_start = true;
  size_t i = 0;
  while (i < code.size()) {
    const char c = code[i];
    size_t end = i;
    if (c == '/' && i + 1 < code.size() && code[i + 1] == '/') {
      end = code.find('\n', i);
      if (end == std::string::npos) end = code.size();
    } else if (c == '/' && i + 1 < code.size() && code[i + 1] == '*') {
      end = code.find("*/", i + 2);
      end = end == std::string::npos ? code.size() : end + 2;
    } else if (c == '#' && line_start) {
      end = endOfDirective(code, i);
    } else if (c == '"') {
      end = opensRawString(code, i) ? endOfRawString(code, i) : endOfQuoted(code, i);
    } else if (c == '\'' && !isDigitSeparator(code, i)) {
      end = endOfQuoted(code, i);
    }
    if (end > i) {
      blank(code, i, end);
      i = end;
      continue;
    }
    if (c == '\n') line_start = true;
    else if (!std::isspace(static_cast<unsigned char>(c))) line_start = false;
    ++i;
  }
  return code;
}

std::string trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

bool startsWithWord(const std::string& text, size_t at, const std::string& word) {
  if (text.compare(at, word.size(), word) != 0) return false;
  if (at > 0 && isIdentifierChar(text[at - 1])) return false;
  return at + word.size() >= text.size() || !isIdentifierChar(text[at + word.size()]);
}

// The index one past the bracket that closes the one at `open`.
size_t pastMatching(const std::string& text, size_t open, char opening, char closing) {
  int depth = 0;
  for (size_t i = open; i < text.size(); ++i) {
    if (text[i] == opening) ++depth;
    if (text[i] == closing && --depth == 0) return i + 1;
  }
  return text.size();
}

// A declaration head without what cannot tell a function from a class or a
// variable: template parameter lists, attributes, alignas(...).
std::string withoutDecorations(std::string head) {
  for (size_t i = 0; i < head.size(); ++i) {
    size_t end = i;
    if (startsWithWord(head, i, "template")) {
      const size_t angle = head.find_first_not_of(" \t\r\n", i + 8);
      if (angle != std::string::npos && head[angle] == '<') end = pastMatching(head, angle, '<', '>');
    } else if (head.compare(i, 2, "[[") == 0) {
      end = pastMatching(head, i, '[', ']');
    } else if (startsWithWord(head, i, "alignas") || startsWithWord(head, i, "__attribute__")) {
      const size_t paren = head.find('(', i);
      if (paren != std::string::npos) end = pastMatching(head, paren, '(', ')');
    }
    if (end > i) head.replace(i, end - i, std::string(end - i, ' '));
  }
  return trim(head);
}

// "operator()", "operator==", "operator bool" become "operator@", so that
// their symbols are not read as brackets or assignments.
std::string withPlainOperators(std::string head) {
  for (size_t at = head.find("operator"); at != std::string::npos; at = head.find("operator", at + 1)) {
    if (!startsWithWord(head, at, "operator")) continue;
    size_t end = head.find_first_not_of(" \t\r\n", at + 8);
    if (end == std::string::npos) break;
    if (head[end] == '(') end = head.find(')', end) + 1;
    end = head.find('(', end);
    if (end == std::string::npos) break;
    head.replace(at, end - at, "operator@");
  }
  return head;
}

// Where the parts of a declaration head sit at its top level (outside
// parentheses and template brackets).
struct HeadLayout {
  size_t first_paren = std::string::npos;      // the parameter list
  size_t first_assignment = std::string::npos;
  size_t class_key = std::string::npos;        // class, struct, union or enum
  size_t single_colon = std::string::npos;     // a base clause or constructor initializers
  int open_parens = 0;                         // unclosed at the end: a brace there is an argument
};

bool isAssignment(const std::string& head, size_t i) {
  if (head[i] != '=') return false;
  const char before = i > 0 ? head[i - 1] : ' ', after = i + 1 < head.size() ? head[i + 1] : ' ';
  return after != '=' && before != '=' && before != '!' && before != '<' && before != '>';
}

bool isSingleColon(const std::string& head, size_t i) {
  return head[i] == ':' && (i == 0 || head[i - 1] != ':') && (i + 1 >= head.size() || head[i + 1] != ':');
}

// A parenthesis that belongs to the return type or a specifier, not the
// parameter list: decltype(...), noexcept(...), ...
bool isSpecifierParen(const std::string& head, size_t paren) {
  size_t end = paren;
  while (end > 0 && head[end - 1] == ' ') --end;
  size_t start = end;
  while (start > 0 && isIdentifierChar(head[start - 1])) --start;
  const std::string word = head.substr(start, end - start);
  return word == "decltype" || word == "noexcept" || word == "sizeof" || word == "throw";
}

HeadLayout layoutOf(const std::string& head) {
  HeadLayout layout;
  int parens = 0, angles = 0;
  for (size_t i = 0; i < head.size(); ++i) {
    const char c = head[i];
    const bool top = parens == 0 && angles == 0;
    if (c == '(') {
      if (top && layout.first_paren == std::string::npos && !isSpecifierParen(head, i)) layout.first_paren = i;
      ++parens;
    } else if (c == ')') {
      parens = std::max(0, parens - 1);
    } else if (parens == 0 && c == '<') {
      ++angles;
    } else if (parens == 0 && c == '>' && (i == 0 || head[i - 1] != '-')) {
      angles = std::max(0, angles - 1);
    } else if (top && isAssignment(head, i) && layout.first_assignment == std::string::npos) {
      layout.first_assignment = i;
    } else if (top && isSingleColon(head, i) && layout.single_colon == std::string::npos) {
      layout.single_colon = i;
    } else if (top && layout.class_key == std::string::npos &&
               (startsWithWord(head, i, "class") || startsWithWord(head, i, "struct") ||
                startsWithWord(head, i, "union") || startsWithWord(head, i, "enum"))) {
      layout.class_key = i;
    }
  }
  layout.open_parens = parens;
  return layout;
}

// What follows a parameter list, without cv-, ref- and exception qualifiers.
std::string withoutQualifiers(std::string after) {
  static const char* const kQualifiers[] = {"const", "volatile", "override", "final", "mutable", "try", "&&", "&"};
  for (bool stripped = true; stripped;) {
    stripped = false;
    after = trim(after);
    if (startsWithWord(after, 0, "noexcept") || startsWithWord(after, 0, "throw")) {
      const size_t word_end = after.find_first_of(" (", 0);
      size_t end = word_end == std::string::npos ? after.size() : word_end;
      const size_t next = after.find_first_not_of(' ', end);
      if (next != std::string::npos && after[next] == '(') end = pastMatching(after, next, '(', ')');
      after.erase(0, end);
      stripped = true;
      continue;
    }
    for (const char* qualifier : kQualifiers) {
      const std::string word = qualifier;
      const bool symbol = !isIdentifierChar(word[0]);
      if (symbol ? after.compare(0, word.size(), word) == 0 : startsWithWord(after, 0, word)) {
        after.erase(0, word.size());
        stripped = true;
        break;
      }
    }
  }
  return after;
}

enum class BraceKind { kScope, kFunction, kInitializer };

// Whether the text after a parameter list ends a function head, so that the
// brace that follows opens its body.
bool endsFunctionHead(const std::string& after_parameters) {
  const std::string after = withoutQualifiers(after_parameters);
  if (after.empty() || after.compare(0, 2, "->") == 0) return true;
  // Constructor initializers: the body follows the last "x_(a)" or "y_{b}";
  // a brace right after a member name initializes that member.
  return after.back() == ')' || after.back() == '}';
}

BraceKind classify(const std::string& raw_head) {
  const std::string head = withPlainOperators(withoutDecorations(raw_head));
  if (head.empty()) return BraceKind::kInitializer;
  if (head == "extern" || head.find("namespace") != std::string::npos) return BraceKind::kScope;
  const HeadLayout layout = layoutOf(head);
  if (layout.open_parens > 0) return BraceKind::kInitializer;  // a default argument, a lambda passed on
  const bool class_first = layout.class_key != std::string::npos &&
                           (layout.first_paren == std::string::npos ||
                            (layout.single_colon != std::string::npos && layout.single_colon < layout.first_paren)) &&
                           (layout.first_assignment == std::string::npos || layout.class_key < layout.first_assignment);
  if (class_first) return BraceKind::kScope;
  if (layout.first_assignment != std::string::npos &&
      (layout.first_paren == std::string::npos || layout.first_assignment < layout.first_paren)) {
    return BraceKind::kInitializer;
  }
  if (layout.first_paren == std::string::npos) return BraceKind::kInitializer;
  const size_t close = pastMatching(head, layout.first_paren, '(', ')');
  return endsFunctionHead(head.substr(close)) ? BraceKind::kFunction : BraceKind::kInitializer;
}

// The name before a function head's parameter list ("Foo::bar", "main").
std::string functionName(const std::string& raw_head) {
  const std::string head = withoutDecorations(raw_head);
  const std::string plain = withPlainOperators(head);
  const size_t paren = layoutOf(plain).first_paren;
  if (paren == std::string::npos) return trim(head);
  size_t end = paren;
  while (end > 0 && plain[end - 1] == ' ') --end;
  size_t start = end;
  while (start > 0) {
    const char c = plain[start - 1];
    if (c == '>') {  // template arguments of a qualifier: Buffer<T>::resize
      int depth = 0;
      do {
        --start;
        depth += plain[start] == '>' ? 1 : plain[start] == '<' ? -1 : 0;
      } while (start > 0 && depth > 0);
    } else if (isIdentifierChar(c) || c == ':' || c == '~' || c == '@') {
      --start;
    } else {
      break;
    }
  }
  std::string name = plain.substr(start, end - start);
  const size_t at = name.find("operator@");
  if (at != std::string::npos) {  // the operator as written
    const size_t written = head.find("operator", start);
    const size_t written_end = head.find('(', head.find_first_not_of(' ', written + 8) + 1);
    name = name.substr(0, at) + trim(head.substr(written, written_end - written));
  }
  const bool macro = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_';
  });
  if (macro) name += plain.substr(paren, pastMatching(plain, paren, '(', ')') - paren);  // TEST(Suite, Name)
  return name;
}

// The declarations of one scope, walked brace by brace.
class DeclarationScanner {
 public:
  explicit DeclarationScanner(const std::string& source) : code_(codeOnly(source)) {
    line_starts_.push_back(0);
    for (size_t i = 0; i < code_.size(); ++i) {
      if (code_[i] == '\n') line_starts_.push_back(i + 1);
    }
  }

  std::vector<FunctionSpan> functions() {
    size_t position = 0;
    while (position < code_.size()) scanScope(position);  // a stray '}' ends a scope early: go on
    return found_;
  }

 private:
  int lineOf(size_t position) const {
    return static_cast<int>(std::upper_bound(line_starts_.begin(), line_starts_.end(), position) -
                            line_starts_.begin());
  }

  // Scans declarations from `position` to the '}' that closes the scope.
  void scanScope(size_t& position) {
    std::string head;
    size_t head_start = std::string::npos;
    auto clear = [&] {
      head.clear();
      head_start = std::string::npos;
    };
    while (position < code_.size()) {
      const char c = code_[position];
      if (c == ';') {
        clear();
      } else if (c == '}') {
        ++position;
        return;
      } else if (c == '{') {
        if (head_start == std::string::npos) head_start = position;
        if (onBrace(position, head, head_start)) clear();
        continue;
      } else {
        if (head_start == std::string::npos && !std::isspace(static_cast<unsigned char>(c))) head_start = position;
        head += c;
        if (c == ':' && isAccessSpecifier(head)) clear();
      }
      ++position;
    }
  }

  static bool isAccessSpecifier(const std::string& head) {
    const std::string text = trim(head);
    return text == "public:" || text == "private:" || text == "protected:" ||
           (text.size() > 1 && text.back() == ':' && text[text.size() - 2] != ':' &&
            trim(text.substr(0, text.size() - 1)).find_first_of(" ()") == std::string::npos &&
            (startsWithWord(text, 0, "public") || startsWithWord(text, 0, "private") ||
             startsWithWord(text, 0, "protected")));
  }

  // Handles the brace at `position` and moves past what it opens; returns
  // whether the declaration ended with it.
  bool onBrace(size_t& position, std::string& head, size_t head_start) {
    const BraceKind kind = classify(head);
    if (kind == BraceKind::kScope) {
      ++position;
      scanScope(position);
      return true;
    }
    const size_t end = pastMatching(code_, position, '{', '}');
    if (kind == BraceKind::kFunction) {
      found_.push_back({"", lineOf(head_start), lineOf(end - 1), functionName(head)});
    } else if (opensLambdaBody(head)) {
      found_.push_back({"", lineOf(head_start), lineOf(end - 1), "lambda in " + declaredName(head)});
    }
    position = end;
    if (kind == BraceKind::kFunction) return true;
    head += "{}";
    return false;
  }

  // A brace in a variable's initializer after ")", "]" or "mutable" opens a
  // lambda's body (a lambda in a constructor's initializers counts toward it).
  static bool opensLambdaBody(const std::string& head) {
    if (layoutOf(withPlainOperators(withoutDecorations(head))).first_assignment == std::string::npos) return false;
    const std::string text = trim(head);
    if (text.empty()) return false;
    return text.back() == ')' || text.back() == ']' ||
           (text.size() >= 7 && startsWithWord(text, text.size() - 7, "mutable"));
  }

  static std::string declaredName(const std::string& head) {
    const size_t assignment = head.find('=');
    std::string before = trim(head.substr(0, assignment));
    size_t start = before.size();
    while (start > 0 && isIdentifierChar(before[start - 1])) --start;
    return before.substr(start);
  }

  std::string code_;
  std::vector<size_t> line_starts_;
  std::vector<FunctionSpan> found_;
};

bool isSourceFile(const fs::path& path) {
  const std::string extension = path.extension().string();
  return extension == ".cpp" || extension == ".hpp" || extension == ".h" || extension == ".cc";
}

}  // namespace

std::vector<FunctionSpan> functionsIn(const std::string& source) { return DeclarationScanner(source).functions(); }

int lineLimitFor(const FunctionSpan& function) {
  return function.name == "main" ? kMaxMainLines : kMaxFunctionLines;
}

std::vector<FunctionSpan> functionsOfTree(const fs::path& repository_root) {
  std::vector<fs::path> files;
  for (const char* top : {"modules", "blackboard", "planners"}) {
    if (!fs::is_directory(repository_root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(repository_root / top)) {
      if (entry.is_regular_file() && isSourceFile(entry.path())) files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<FunctionSpan> functions;
  for (const fs::path& file : files) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    for (FunctionSpan function : functionsIn(text.str())) {
      function.file = fs::relative(file, repository_root).generic_string();
      functions.push_back(std::move(function));
    }
  }
  return functions;
}

std::vector<FunctionSpan> overlongFunctions(const fs::path& repository_root) {
  std::vector<FunctionSpan> overlong;
  for (const FunctionSpan& function : functionsOfTree(repository_root)) {
    if (function.lines() > lineLimitFor(function)) overlong.push_back(function);
  }
  return overlong;
}

std::string describe(const FunctionSpan& function) {
  return function.file + ":" + std::to_string(function.first_line) + ": " + function.name + " (" +
         std::to_string(function.lines()) + " lines)";
}

}  // namespace beft::rules
