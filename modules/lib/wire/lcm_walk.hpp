// Walks the bytes of an encoded LCM struct by its .lcm definition
// (lcm_schema.hpp) and hands every value to a visitor: one walk for every
// reader of messages as data (the readable decoder, the JSON of the Foxglove
// bridge). The bytes are untrusted: every read is bounds-checked, an array
// length is checked against the bytes left before any element is read, and
// whatever is wrong throws LcmWalkError naming the field.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "lib/wire/lcm_schema.hpp"

namespace beft::wire {

// Bytes that do not hold what the definition says: the message names the
// field and where the bytes ended.
class LcmWalkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Big-endian reads with bounds checks (LCM's encoding).
class LcmReader {
 public:
  LcmReader(const uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::size_t position() const { return position_; }
  std::size_t remaining() const { return size_ - position_; }
  const uint8_t* here() const { return data_ + position_; }

  uint64_t readUnsigned(int bytes, const std::string& field);
  int64_t readSigned(int bytes, const std::string& field);
  double readDouble(const std::string& field);
  float readFloat(const std::string& field);
  // Length (with its final '\0') then the characters; refuses a length < 1
  // and a string that does not end in '\0'.
  std::string readString(const std::string& field);
  void skip(std::size_t bytes, const std::string& field);

 private:
  void need(std::size_t bytes, const std::string& field) const;

  const uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

// One primitive value as read.
struct LcmValue {
  enum class Kind { kInteger, kBoolean, kFloat, kDouble, kString };
  Kind kind = Kind::kInteger;
  int64_t integer = 0;  // kInteger and kBoolean (the byte as sent: 0, 1 or another)
  double number = 0;    // kFloat and kDouble
  std::string text;     // kString (may hold any bytes but '\0' at its end)
};

// What a walk reports, in the order of the bytes. label names the value for
// people: "name" for a member, "name[2]" for an element of an array of
// structs or arrays; elements of a number/string array carry the array's
// label.
class LcmVisitor {
 public:
  virtual ~LcmVisitor() = default;
  // A primitive member, or one element of a number/string array.
  virtual void scalar(const LcmMember& member, const std::string& label, const LcmValue& value) = 0;
  // The innermost dimension of a byte array: its bytes, in the message.
  virtual void bytes(const LcmMember& member, const std::string& label, const uint8_t* data,
                     std::size_t count) = 0;
  // A struct member or an element of a struct array; its members follow,
  // then endStruct.
  virtual void beginStruct(const LcmMember& member, const std::string& label, const LcmStruct& type) = 0;
  virtual void endStruct() = 0;
  // An array (not of bytes at its innermost dimension): of_scalars when its
  // elements are numbers or strings. Each element of an array of structs or
  // arrays is announced by element(); then endArray.
  virtual void beginArray(const LcmMember& member, const std::string& label, int64_t count,
                          bool of_scalars) = 0;
  virtual void element(int64_t /*index*/) {}
  virtual void endArray() = 0;
};

// Reads the members of one struct (no fingerprint) from reader, reporting
// each to visitor. Throws LcmWalkError (and lets the visitor's exceptions
// through).
void walkLcmStruct(const LcmTypeSet& types, const LcmStruct& type, LcmReader& reader, LcmVisitor& visitor);

// Checks that a whole encoded message is of type (its 8-byte fingerprint)
// and walks it; refuses bytes left after the last member. Throws
// LcmWalkError.
void walkLcmMessage(const LcmTypeSet& types, const LcmStruct& type, const uint8_t* data, std::size_t size,
                    LcmVisitor& visitor);

}  // namespace beft::wire
