// beft-key: makes the shared key of an authenticated run (./beft key new FILE).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "lib/common/command_line.hpp"
#include "lib/transport/message_key.hpp"

namespace {

struct Options {
  std::string file;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "The key of an authenticated run: every process of a run started with --key FILE (or BEFT_KEY_FILE=FILE) "
      "tags each message it publishes with a MAC of this key (keyed BLAKE2b, libsodium) and refuses every "
      "message without a valid tag, so a program on the network without the key can neither join the run nor "
      "change its messages. Every host of a distributed run needs a copy of the same file.",
      "beft-key");
  app.require_subcommand(1);
  CLI::App* make = app.add_subcommand(
      "new", "write a new random key to FILE: 32 random bytes as 64 hexadecimal digits, readable by its owner "
             "only (mode 0600); an existing FILE is never replaced");
  make->add_option("file", o.file, "the key file to write")->required();
  return beft::parseCommandLine(app, argc, argv);
}

std::string hexText(const beft::transport::MessageKey& key) {
  std::string text;
  char digits[3];
  for (uint8_t byte : key.bytes()) {
    std::snprintf(digits, sizeof digits, "%02x", byte);
    text += digits;
  }
  return text + "\n";
}

// Creates `path` (never over an existing file or through a link) with mode
// 0600 whatever the umask, and writes a new key; "" or what went wrong.
std::string writeNewKey(const std::string& path) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) {
    if (errno == EEXIST) return path + " exists: not replaced (write the new key to another file)";
    return "cannot create " + path + ": " + std::strerror(errno);
  }
  const std::string text = hexText(beft::transport::MessageKey::random());
  const bool written = fchmod(fd, 0600) == 0 &&
                       write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) && fsync(fd) == 0;
  const std::string why = written ? "" : "cannot write " + path + ": " + std::strerror(errno);
  close(fd);
  if (!written) unlink(path.c_str());
  return why;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  const std::string problem = writeNewKey(options.file);
  if (!problem.empty()) {
    std::fprintf(stderr, "beft-key: error: %s\n", problem.c_str());
    return 1;
  }
  std::printf("beft-key: wrote a new key to %s (mode 0600); run with ./beft run SCENARIO.xml --key %s "
              "(or BEFT_KEY_FILE=%s)\n",
              options.file.c_str(), options.file.c_str(), options.file.c_str());
  return 0;
}
