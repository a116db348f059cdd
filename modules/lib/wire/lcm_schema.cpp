#include "lib/wire/lcm_schema.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

namespace beft::wire {
namespace {

const std::set<std::string>& primitives() {
  static const std::set<std::string> names = {"int8_t", "int16_t", "int32_t", "int64_t", "byte",
                                              "float",  "double",  "string",  "boolean"};
  return names;
}

struct Token {
  std::string text;
  int line = 0;
};

struct Tokens {
  std::vector<Token> tokens;
  std::map<int, std::string> line_comments;  // text of the // comment ending each line
};

// Splits .lcm text into identifiers/numbers and single punctuation marks,
// dropping /* */ comments and keeping each line's // comment aside.
Tokens tokenize(const std::string& source, const std::string& text) {
  Tokens result;
  std::vector<Token>& tokens = result.tokens;
  int line = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      const std::size_t start = i + 2;
      while (i < text.size() && text[i] != '\n') ++i;
      result.line_comments[line] = text.substr(start, i - start);
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      const int start_line = line;
      i += 2;
      while (i + 1 < text.size() && !(text[i] == '*' && text[i + 1] == '/')) {
        if (text[i] == '\n') ++line;
        ++i;
      }
      if (i + 1 >= text.size())
        throw SchemaError(source + ":" + std::to_string(start_line) + ": unterminated /* comment");
      i += 2;
    } else if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-' ||
               c == '+') {
      std::size_t end = i + 1;
      while (end < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_' ||
              text[end] == '.' || ((text[end] == '-' || text[end] == '+') &&
                                   (text[end - 1] == 'e' || text[end - 1] == 'E'))))
        ++end;
      tokens.push_back({text.substr(i, end - i), line});
      i = end;
    } else if (std::string("{}[];=,").find(c) != std::string::npos) {
      tokens.push_back({std::string(1, c), line});
      ++i;
    } else {
      throw SchemaError(source + ":" + std::to_string(line) + ": unexpected character '" +
                        std::string(1, c) + "'");
    }
  }
  return result;
}

bool isIdentifier(const std::string& text) {
  if (text.empty() || !(std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_'))
    return false;
  return std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
  });
}

bool isNumber(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

class Parser {
 public:
  Parser(std::string source, Tokens tokens)
      : source_(std::move(source)), tokens_(std::move(tokens.tokens)), comments_(std::move(tokens.line_comments)) {}

  std::vector<LcmStruct> parse() {
    std::string package;
    std::vector<LcmStruct> structs;
    while (!atEnd()) {
      const Token& keyword = next("'package' or 'struct'");
      if (keyword.text == "package") {
        package = expectIdentifier("package name").text;
        expect(";");
      } else if (keyword.text == "struct") {
        structs.push_back(parseStruct(package));
      } else {
        fail(keyword, "expected 'package' or 'struct', found '" + keyword.text + "'");
      }
    }
    return structs;
  }

 private:
  LcmStruct parseStruct(const std::string& package) {
    LcmStruct result;
    result.package = package;
    result.source = source_;
    result.name = expectIdentifier("struct name").text;
    expect("{");
    while (peek("'}' or a member").text != "}") {
      if (peek("").text == "const")
        parseConstants(result);
      else
        parseMembers(result);
    }
    expect("}");
    return result;
  }

  void parseConstants(LcmStruct& result) {
    next("const");
    const Token& type = expectIdentifier("constant type");
    if (!isLcmPrimitive(type.text) || type.text == "string" || type.text == "boolean" || type.text == "byte")
      fail(type, "constants must be int8_t, int16_t, int32_t, int64_t, float or double");
    while (true) {
      LcmConstant constant;
      constant.type = type.text;
      constant.name = expectIdentifier("constant name").text;
      expect("=");
      constant.value = next("constant value").text;
      result.constants.push_back(constant);
      if (peek("',' or ';'").text == ",") {
        next(",");
        continue;
      }
      expect(";");
      return;
    }
  }

  void parseMembers(LcmStruct& result) {
    const Token& type = expectIdentifier("member type");
    std::string type_name = type.text;
    if (!isLcmPrimitive(type_name) && type_name.find('.') == std::string::npos && !result.package.empty())
      type_name = result.package + "." + type_name;
    while (true) {
      LcmMember member;
      member.type = type_name;
      const Token& name = expectIdentifier("member name");
      member.name = name.text;
      if (auto comment = comments_.find(name.line); comment != comments_.end()) member.comment = comment->second;
      for (const auto& existing : result.members)
        if (existing.name == member.name) fail(name, "member '" + member.name + "' declared twice");
      while (peek("'[', ',' or ';'").text == "[") {
        next("[");
        const Token& size = next("array size");
        LcmDimension dimension;
        dimension.variable = !isNumber(size.text);
        dimension.size = size.text;
        if (dimension.variable && !isIdentifier(size.text))
          fail(size, "array size must be a number or a member name, found '" + size.text + "'");
        member.dimensions.push_back(dimension);
        expect("]");
      }
      result.members.push_back(member);
      if (peek("',' or ';'").text == ",") {
        next(",");
        continue;
      }
      expect(";");
      return;
    }
  }

  bool atEnd() const { return position_ >= tokens_.size(); }

  const Token& peek(const std::string& what) const {
    if (atEnd()) failAtEnd(what);
    return tokens_[position_];
  }

  const Token& next(const std::string& what) {
    const Token& token = peek(what);
    ++position_;
    return token;
  }

  void expect(const std::string& text) {
    const Token& token = next("'" + text + "'");
    if (token.text != text) fail(token, "expected '" + text + "', found '" + token.text + "'");
  }

  const Token& expectIdentifier(const std::string& what) {
    const Token& token = next(what);
    if (!isIdentifier(token.text)) fail(token, "expected " + what + ", found '" + token.text + "'");
    return token;
  }

  [[noreturn]] void fail(const Token& token, const std::string& why) const {
    throw SchemaError(source_ + ":" + std::to_string(token.line) + ": " + why);
  }

  [[noreturn]] void failAtEnd(const std::string& what) const {
    const int line = tokens_.empty() ? 1 : tokens_.back().line;
    throw SchemaError(source_ + ":" + std::to_string(line) + ": unexpected end of file, expected " + what);
  }

  std::string source_;
  std::vector<Token> tokens_;
  std::map<int, std::string> comments_;
  std::size_t position_ = 0;
};

// lcm-gen's hash steps (lcmgen.c): a shift-xor over the bytes of each name.
int64_t hashUpdate(int64_t v, char c) {
  const uint64_t shifted_left = static_cast<uint64_t>(v) << 8;
  const int64_t shifted_right = v >> 55;  // arithmetic shift, as in lcm-gen
  return static_cast<int64_t>((shifted_left ^ static_cast<uint64_t>(shifted_right)) +
                              static_cast<uint64_t>(static_cast<int64_t>(c)));
}

int64_t hashString(int64_t v, const std::string& text) {
  v = hashUpdate(v, static_cast<char>(text.size()));
  for (char c : text) v = hashUpdate(v, c);
  return v;
}

bool isIntegerType(const std::string& type) {
  return type == "int8_t" || type == "int16_t" || type == "int32_t" || type == "int64_t";
}

}  // namespace

bool isLcmPrimitive(const std::string& type) { return primitives().count(type) > 0; }

int64_t lcmBaseHash(const LcmStruct& lcm_struct) {
  // The struct's own name is left out on purpose (renaming keeps the hash);
  // member struct types contribute their own hashes, added by the caller.
  int64_t v = 0x12345678;
  for (const auto& member : lcm_struct.members) {
    v = hashString(v, member.name);
    if (isLcmPrimitive(member.type)) v = hashString(v, member.type);
    v = hashUpdate(v, static_cast<char>(member.dimensions.size()));
    for (const auto& dimension : member.dimensions) {
      v = hashUpdate(v, dimension.variable ? 1 : 0);  // lcm-gen: LCM_CONST = 0, LCM_VAR = 1
      v = hashString(v, dimension.size);
    }
  }
  return v;
}

void LcmTypeSet::addSchema(const std::string& source, const std::string& text) {
  Parser parser(source, tokenize(source, text));
  for (auto& parsed : parser.parse()) {
    const std::string name = parsed.fullName();
    if (auto existing = structs_.find(name); existing != structs_.end())
      throw SchemaError(source + ": struct " + name + " is already defined in " + existing->second.source);
    structs_.emplace(name, std::move(parsed));
  }
}

void LcmTypeSet::validate() const {
  for (const auto& [name, lcm_struct] : structs_) {
    for (std::size_t i = 0; i < lcm_struct.members.size(); ++i) {
      const LcmMember& member = lcm_struct.members[i];
      if (!isLcmPrimitive(member.type) && !structs_.count(member.type))
        throw SchemaError(lcm_struct.source + ": " + name + "." + member.name + " has unknown type " +
                          member.type);
      for (const auto& dimension : member.dimensions) {
        if (!dimension.variable) continue;
        auto size_member = std::find_if(lcm_struct.members.begin(), lcm_struct.members.begin() + i,
                                        [&](const LcmMember& m) { return m.name == dimension.size; });
        if (size_member == lcm_struct.members.begin() + i)
          throw SchemaError(lcm_struct.source + ": " + name + "." + member.name + " is sized by '" +
                            dimension.size + "', which is not an earlier member");
        if (!isIntegerType(size_member->type) || !size_member->dimensions.empty())
          throw SchemaError(lcm_struct.source + ": " + name + "." + member.name + " is sized by '" +
                            dimension.size + "', which is not an integer");
      }
    }
  }
}

void LcmTypeSet::finalize() {
  validate();
  fingerprints_.clear();
  by_fingerprint_.clear();
  for (const auto& [name, lcm_struct] : structs_) {
    const uint64_t value = fingerprint(name);
    fingerprints_[name] = value;
    by_fingerprint_[value] = name;
  }
}

const LcmStruct* LcmTypeSet::find(const std::string& full_name) const {
  auto it = structs_.find(full_name);
  return it == structs_.end() ? nullptr : &it->second;
}

const LcmStruct* LcmTypeSet::findByFingerprint(uint64_t value) const {
  auto it = by_fingerprint_.find(value);
  return it == by_fingerprint_.end() ? nullptr : find(it->second);
}

uint64_t LcmTypeSet::fingerprint(const std::string& full_name) const {
  if (auto cached = fingerprints_.find(full_name); cached != fingerprints_.end()) return cached->second;
  if (!structs_.count(full_name)) throw SchemaError("unknown message type " + full_name);
  std::vector<std::string> parents;
  return computeHash(full_name, parents);
}

uint64_t LcmTypeSet::computeHash(const std::string& full_name, std::vector<std::string>& parents) const {
  // As lcm-gen's _computeHash: a type already being hashed further up (a
  // recursive type) contributes 0; member struct hashes are summed in; the
  // result is rotated left by one bit.
  if (std::find(parents.begin(), parents.end(), full_name) != parents.end()) return 0;
  const LcmStruct* lcm_struct = find(full_name);
  if (!lcm_struct) throw SchemaError("unknown message type " + full_name);
  parents.push_back(full_name);
  uint64_t hash = static_cast<uint64_t>(lcmBaseHash(*lcm_struct));
  for (const auto& member : lcm_struct->members)
    if (!isLcmPrimitive(member.type)) hash += computeHash(member.type, parents);
  parents.pop_back();
  return (hash << 1) + ((hash >> 63) & 1);
}

std::vector<std::string> LcmTypeSet::typeNames() const {
  std::vector<std::string> names;
  for (const auto& entry : structs_) names.push_back(entry.first);
  return names;
}

}  // namespace beft::wire
