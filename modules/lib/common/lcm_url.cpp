#include "lib/common/lcm_url.hpp"

#include <cstdlib>

namespace beft {

std::string defaultLcmUrl() {
  if (const char* env = std::getenv("BEFT_LCM_URL"); env && *env) return env;
  return lcmUrlForPort(7667);
}

std::string lcmUrlForPort(int port, int ttl) {
  // recv_buf_size: camera frames and maps are several UDP fragments each.
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=" + std::to_string(ttl) +
         "&recv_buf_size=8388608";
}

}  // namespace beft
