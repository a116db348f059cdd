#include "lib/petri/xml_encoding.hpp"

#include <iconv.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <stdexcept>

namespace beft::arbiter {

namespace {

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Where the declaration's encoding value sits: [begin, end) of the name.
bool findEncodingValue(const std::string& bytes, size_t& begin, size_t& end) {
  if (bytes.compare(0, 5, "<?xml") != 0) return false;
  const size_t close = bytes.find("?>");
  if (close == std::string::npos) return false;
  const size_t key = bytes.find("encoding", 5);
  if (key == std::string::npos || key > close) return false;
  size_t at = bytes.find_first_not_of(" \t\r\n", key + 8);
  if (at == std::string::npos || bytes[at] != '=') return false;
  at = bytes.find_first_not_of(" \t\r\n", at + 1);
  if (at == std::string::npos || (bytes[at] != '"' && bytes[at] != '\'')) return false;
  const size_t quote_end = bytes.find(bytes[at], at + 1);
  if (quote_end == std::string::npos || quote_end > close) return false;
  begin = at + 1;
  end = quote_end;
  return true;
}

bool isUtf8Name(const std::string& name) {
  const std::string n = lowercase(name);
  return n.empty() || n == "utf-8" || n == "utf8" || n == "us-ascii" || n == "ascii";
}

std::string convert(const std::string& bytes, const std::string& from) {
  iconv_t converter = iconv_open("UTF-8", from.c_str());
  if (converter == reinterpret_cast<iconv_t>(-1))
    throw std::runtime_error("the encoding '" + from + "' is not known");
  std::string out(bytes.size() * 4 + 16, '\0');
  char* in_ptr = const_cast<char*>(bytes.data());
  size_t in_left = bytes.size();
  char* out_ptr = out.data();
  size_t out_left = out.size();
  const size_t result = iconv(converter, &in_ptr, &in_left, &out_ptr, &out_left);
  const int error = errno;
  iconv_close(converter);
  if (result == static_cast<size_t>(-1)) {
    const size_t offset = bytes.size() - in_left;
    throw std::runtime_error("byte " + std::to_string(offset) + " is not valid " + from +
                             (error == EINVAL ? " (the file ends inside a character)" : ""));
  }
  out.resize(out.size() - out_left);
  return out;
}

}  // namespace

std::string declaredXmlEncoding(const std::string& bytes) {
  size_t begin = 0, end = 0;
  return findEncodingValue(bytes, begin, end) ? bytes.substr(begin, end - begin) : "";
}

std::string xmlTextAsUtf8(const std::string& bytes) {
  // UTF-16 by byte-order mark: the declaration is itself UTF-16, so convert first.
  if (bytes.size() >= 2 && ((bytes[0] == '\xFF' && bytes[1] == '\xFE') || (bytes[0] == '\xFE' && bytes[1] == '\xFF'))) {
    std::string text = convert(bytes, "UTF-16");
    size_t begin = 0, end = 0;
    if (findEncodingValue(text, begin, end)) text.replace(begin, end - begin, "UTF-8");
    return text;
  }
  size_t begin = 0, end = 0;
  if (!findEncodingValue(bytes, begin, end)) return bytes;
  const std::string name = bytes.substr(begin, end - begin);
  if (isUtf8Name(name)) return bytes;
  std::string text = convert(bytes, name);
  if (findEncodingValue(text, begin, end)) text.replace(begin, end - begin, "UTF-8");
  return text;
}

}  // namespace beft::arbiter
