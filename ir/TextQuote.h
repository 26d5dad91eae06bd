// Quoted strings of ncc's text forms (NC IR, Motion IR): one set of escapes for the printers
// and the parsers, so whatever a printer writes reads back as the same bytes.
// Escapes: \" \\ \n \r \t, and \xHH for the other control bytes (< 0x20, 0x7f); every other
// byte (UTF-8 included) is written as it is.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace ncc::text {

// Appends `s` escaped, without quotes; json: control bytes as \u00HH (JSON), else \xHH.
void appendEscaped(std::string &out, std::string_view s, bool json);
// Appends `s` in double quotes, escaped.
void appendQuoted(std::string &out, std::string_view s);
inline std::string quoted(std::string_view s) {
  std::string o;
  appendQuoted(o, s);
  return o;
}

// Decodes the escape whose backslash is at s[pos - 1], appending the byte to `out` and moving
// pos past it. On a bad escape returns false with `error` set and pos unchanged.
bool decodeEscape(std::string_view s, size_t &pos, std::string &out, const char *&error);

}  // namespace ncc::text
