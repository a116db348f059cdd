// XML text in the encoding its declaration names, made UTF-8 for the parser
// (tinyxml2 reads UTF-8 only). Editors write ISO-8859-1 and others.
#pragma once

#include <string>

namespace beft::arbiter {

// Returns the text as UTF-8, its declaration saying so; line breaks are kept,
// so line numbers stay those of the file. A UTF-16 file is recognised by its
// byte-order mark. Throws std::runtime_error ("the encoding 'X' is not known",
// "byte N is not valid ISO-8859-1 ...") for what cannot be converted.
std::string xmlTextAsUtf8(const std::string& bytes);

// The encoding named in the XML declaration, "" when none is given.
std::string declaredXmlEncoding(const std::string& bytes);

}  // namespace beft::arbiter
