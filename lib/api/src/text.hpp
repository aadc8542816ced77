// Text as lab PCs write it (README, "File formats"): UTF-8, or Windows-1252 / Latin-1 where a line
// is not UTF-8 (a German DAQ's "Weg [µm]"), and names printed as characters in messages.
#pragma once
#include <string>

namespace vibrofric::detail {

// True if s is well-formed UTF-8 (no overlong forms, surrogates or code points above U+10FFFF).
bool is_utf8(const std::string& s);

// s read as Windows-1252 (Latin-1 where 1252 leaves a byte undefined), written as UTF-8.
std::string utf8_from_cp1252(const std::string& s);

// s unchanged where it is UTF-8, else read as Windows-1252.
std::string as_utf8(const std::string& s);

}  // namespace vibrofric::detail
