// The text of every file `beft-new-expert` writes, with {{key}} holes that
// code_blocks fills from the expert's spec. The expert's own header is a
// hole too ({{own_header}}): an include line spelt out here would be taken
// for one of this file's by the layer check.
#pragma once

#include <map>
#include <string>

namespace beft::new_expert::templates {

extern const char* const kExpertCMakeLists;  // modules/experts/NAME/CMakeLists.txt
extern const char* const kMain;              // modules/experts/NAME/main.cpp
extern const char* const kHeader;            // modules/experts/NAME/NAME_expert.hpp
extern const char* const kSource;            // modules/experts/NAME/NAME_expert.cpp
extern const char* const kTestCMakeLists;    // tests/experts/NAME/CMakeLists.txt
extern const char* const kTest;              // tests/experts/NAME/test_NAME_expert.cpp
extern const char* const kMessageType;       // lcmtypes/TYPE.lcm of a new channel

// text with every {{key}} (lowercase letters and '_') replaced by its value;
// other double braces stay; std::logic_error for a hole with no value (a
// template and its filler out of step).
std::string fill(const std::string& text, const std::map<std::string, std::string>& values);

}  // namespace beft::new_expert::templates
