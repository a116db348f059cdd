#include "services/bridge/static_files.hpp"

#include <algorithm>
#include <cctype>
#include <map>

namespace beft::bridge {

namespace {

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "%20" and the like decoded; nothing for a bad escape or a NUL.
std::optional<std::string> percentDecoded(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '%') {
      if (i + 2 >= text.size()) return std::nullopt;
      const int high = hexValue(text[i + 1]), low = hexValue(text[i + 2]);
      if (high < 0 || low < 0) return std::nullopt;
      c = static_cast<char>(high * 16 + low);
      i += 2;
    }
    if (c == '\0') return std::nullopt;
    out.push_back(c);
  }
  return out;
}

// Whether `inner` lies within `outer` (both canonical).
bool inside(const std::filesystem::path& outer, const std::filesystem::path& inner) {
  auto o = outer.begin(), i = inner.begin();
  for (; o != outer.end(); ++o, ++i)
    if (i == inner.end() || *o != *i) return false;
  return true;
}

}  // namespace

std::optional<std::filesystem::path> resolveStaticFile(const std::filesystem::path& root, std::string_view target) {
  const std::size_t end = target.find_first_of("?#");
  const std::optional<std::string> decoded = percentDecoded(target.substr(0, end));
  if (!decoded || decoded->empty() || decoded->front() != '/') return std::nullopt;
  std::filesystem::path relative;
  std::size_t start = 1;
  while (start <= decoded->size()) {
    const std::size_t slash = std::min(decoded->find('/', start), decoded->size());
    const std::string segment = decoded->substr(start, slash - start);
    if (segment == "..") return std::nullopt;  // refused outright, even where it would stay inside
    if (!segment.empty() && segment != ".") {
      if (segment.find('\\') != std::string::npos) return std::nullopt;
      relative /= segment;
    }
    start = slash + 1;
  }
  std::error_code error;
  const std::filesystem::path base = std::filesystem::canonical(root, error);
  if (error) return std::nullopt;
  std::filesystem::path file = std::filesystem::canonical(base / relative, error);
  if (error || !inside(base, file)) return std::nullopt;
  if (std::filesystem::is_directory(file, error)) file /= "index.html";
  file = std::filesystem::canonical(file, error);  // the index may be a link pointing out
  if (error || !inside(base, file) || !std::filesystem::is_regular_file(file, error)) return std::nullopt;
  return file;
}

std::string contentTypeOf(const std::filesystem::path& file) {
  static const std::map<std::string, std::string> types = {
      {".html", "text/html; charset=utf-8"}, {".htm", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"}, {".mjs", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},   {".json", "application/json"},
      {".map", "application/json"},          {".svg", "image/svg+xml"},
      {".png", "image/png"},                 {".jpg", "image/jpeg"},
      {".jpeg", "image/jpeg"},               {".gif", "image/gif"},
      {".ico", "image/x-icon"},              {".webp", "image/webp"},
      {".wasm", "application/wasm"},         {".txt", "text/plain; charset=utf-8"},
      {".woff", "font/woff"},                {".woff2", "font/woff2"},
      {".ttf", "font/ttf"}};
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const auto known = types.find(extension);
  return known == types.end() ? "application/octet-stream" : known->second;
}

}  // namespace beft::bridge
