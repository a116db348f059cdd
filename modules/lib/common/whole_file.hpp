// Files written whole or not at all: the bytes go to a partial file beside
// the target (same folder, same extension, so tools that pick a format by
// the name still do) and are renamed over it only when complete. A program
// killed mid-write leaves the old file, or none, never half of one.
#pragma once

#include <string>

namespace beft {

// ".NAME.partial-PID.EXT" in the folder of `path`.
std::string partialPathFor(const std::string& path);
// Renames a complete partial file over `path`; throws std::runtime_error.
void commitPartial(const std::string& partial, const std::string& path);
// Both steps for bytes in memory; throws std::runtime_error naming the file.
void writeWholeFile(const std::string& path, const std::string& bytes);

}  // namespace beft
