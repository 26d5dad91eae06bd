#include "ir/TextQuote.h"

#include <fmt/format.h>

namespace ncc::text {

namespace {
// The one-letter escapes: the byte and the letter after the backslash.
constexpr char kEscapes[][2] = {{'"', '"'}, {'\\', '\\'}, {'\n', 'n'}, {'\t', 't'}, {'\r', 'r'}};

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
}  // namespace

void appendEscaped(std::string &o, std::string_view s, bool json) {
  for (unsigned char c : s) {
    bool done = false;
    for (auto &e : kEscapes)
      if (c == (unsigned char)e[0]) {
        o += '\\';
        o += e[1];
        done = true;
        break;
      }
    if (done) continue;
    if (json && c < 0x20) fmt::format_to(std::back_inserter(o), "\\u{:04x}", c);
    else if (!json && (c < 0x20 || c == 0x7f)) fmt::format_to(std::back_inserter(o), "\\x{:02x}", c);
    else o += (char)c;
  }
}

void appendQuoted(std::string &o, std::string_view s) {
  o += '"';
  appendEscaped(o, s, false);
  o += '"';
}

bool decodeEscape(std::string_view s, size_t &pos, std::string &out, const char *&error) {
  char e = pos < s.size() ? s[pos] : '\0';
  for (auto &x : kEscapes)
    if (e == x[1]) {
      out += x[0];
      ++pos;
      return true;
    }
  if (e != 'x') {
    error = "unknown escape in string";
    return false;
  }
  int h = pos + 2 < s.size() ? hexValue(s[pos + 1]) : -1;
  int l = h >= 0 ? hexValue(s[pos + 2]) : -1;
  if (l < 0) {
    error = "'\\x' needs two hex digits";
    return false;
  }
  out += (char)(h * 16 + l);
  pos += 3;
  return true;
}

}  // namespace ncc::text
