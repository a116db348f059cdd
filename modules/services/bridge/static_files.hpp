// The web page's files, served over plain HTTP beside the WebSocket: only
// files inside the page's directory, whatever the request's path says.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace beft::bridge {

// The file a request target ("/", "/app.js?v=2", "/img/a%20b.png") names
// inside `root`: "/" and a directory mean its index.html. Nothing for a
// path that leaves `root` ("..", an absolute or encoded one, a symbolic link
// pointing out), a malformed escape, a NUL, or a file that is not there.
std::optional<std::filesystem::path> resolveStaticFile(const std::filesystem::path& root, std::string_view target);

// The Content-Type of a file, by its extension ("application/octet-stream" when unknown).
std::string contentTypeOf(const std::filesystem::path& file);

}  // namespace beft::bridge
