#include "lib/launch/run_key.hpp"

#include <cstdlib>
#include <filesystem>

#include "lib/launch/launch_file.hpp"
#include "lib/transport/message_key.hpp"

namespace beft::launch {

std::string runKeyFile(const std::string& option) {
  std::string path = option;
  if (path.empty())
    if (const char* variable = std::getenv("BEFT_KEY_FILE")) path = variable;
  if (path.empty()) return "";
  std::string why;
  if (!transport::MessageKey::fromFile(path, &why)) throw LaunchError("the run's key: " + why);
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  if (!error) path = absolute.lexically_normal().string();
  setenv("BEFT_KEY_FILE", path.c_str(), 1);
  return path;
}

}  // namespace beft::launch
