// The message types as data: .lcm definitions parsed at run time, with the
// fingerprints lcm-gen gives them, so any beft message can be decoded and
// printed without a hand-written printer per type.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace beft::wire {

// A .lcm file that does not parse: the message names the file and the line.
class SchemaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LcmDimension {
  bool variable = false;  // sized by an earlier member (e.g. [num_percepts])
  std::string size;       // that member's name, or the constant length
};

struct LcmMember {
  std::string name;
  std::string type;  // primitive ("int32_t", "string", ...) or "package.struct_t"
  std::vector<LcmDimension> dimensions;
  // The // comment on the member's line: it declares what the message guard
  // checks beyond the layout ("STATUS_*": one of those constants; "NaN":
  // may be NaN; ">= 0": lower bound).
  std::string comment;
};

struct LcmConstant {
  std::string type;
  std::string name;
  std::string value;  // as written in the .lcm file
};

struct LcmStruct {
  std::string package;
  std::string name;
  std::vector<LcmMember> members;
  std::vector<LcmConstant> constants;
  std::string source;  // file it came from, for messages

  std::string fullName() const { return package.empty() ? name : package + "." + name; }
};

bool isLcmPrimitive(const std::string& type);

// Every struct of a set of .lcm files, with their fingerprints.
class LcmTypeSet {
 public:
  // Parses one .lcm file's text; source names it in error messages.
  // Throws SchemaError.
  void addSchema(const std::string& source, const std::string& text);

  // Call once every file is added: checks that every referenced struct is
  // known and every variable dimension names an earlier integer member, then
  // computes the fingerprints. Throws SchemaError. After it, the lookups
  // below are read-only and safe from several threads.
  void finalize();

  const LcmStruct* find(const std::string& full_name) const;
  // The struct whose fingerprint is this, or null (needs finalize()).
  const LcmStruct* findByFingerprint(uint64_t fingerprint) const;
  // The fingerprint lcm-gen computes for a struct (what getHash() returns and
  // what an encoded message starts with). Throws SchemaError if unknown.
  uint64_t fingerprint(const std::string& full_name) const;

  std::vector<std::string> typeNames() const;

 private:
  void validate() const;
  uint64_t computeHash(const std::string& full_name, std::vector<std::string>& parents) const;

  std::map<std::string, LcmStruct> structs_;
  std::map<std::string, uint64_t> fingerprints_;
  std::map<uint64_t, std::string> by_fingerprint_;
};

// lcm-gen's hash of one struct's own members (names, primitive types,
// dimensions), before the member structs' hashes are added.
int64_t lcmBaseHash(const LcmStruct& lcm_struct);

}  // namespace beft::wire
