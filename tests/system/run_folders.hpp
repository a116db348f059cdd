// The folders the system tests run in (/tmp/beft_<tag>_XXXXXX): a run's log,
// report and process output. A test program that passed removes the ones it
// made when it ends; one that failed keeps them, and names them, for a person
// to look into. BEFT_KEEP_TEST_DIRS=1 keeps them always.
#pragma once

#include <string>

namespace beft::system_test {

// A new, empty folder /tmp/beft_<tag>_XXXXXX, removed at the end of the
// program if every test passed.
std::string makeTempDir(const std::string& tag);

}  // namespace beft::system_test
