#include "frontend/heidenhain/Lexer.h"

#include <cctype>
#include <cstdlib>

namespace ncc::hei {

namespace {
bool isLetter(unsigned char c) { return std::isalpha(c) || c == '_' || c >= 0x80; }

// The control's typographic quotes (the manual prints “…“) read as '"'.
size_t quoteAt(std::string_view s, size_t i) {
  if (s[i] == '"') return 1;
  if (s.substr(i, 3) == "\xE2\x80\x9C" || s.substr(i, 3) == "\xE2\x80\x9D" || s.substr(i, 3) == "\xE2\x80\x9E") return 3;
  return 0;
}

// Where the `;` comment starts (outside strings), npos when none.
size_t commentStart(std::string_view s) {
  bool str = false;
  for (size_t i = 0; i < s.size(); ++i) {
    if (size_t q = quoteAt(s, i)) {
      str = !str;
      i += q - 1;
    } else if (!str && s[i] == ';') {
      return i;
    }
  }
  return std::string_view::npos;
}

void lexText(std::string_view s, size_t from, uint32_t file, uint32_t line, std::vector<Token> &out, LexResult &r) {
  size_t i = from;
  while (i < s.size()) {
    unsigned char c = (unsigned char)s[i];
    Token t;
    t.line = line;
    t.col = (uint32_t)i + 1;
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++i;
      continue;
    }
    if (size_t q = quoteAt(s, i)) {
      size_t j = i + q;
      std::string v;
      while (j < s.size() && !quoteAt(s, j)) v += s[j++];
      if (j >= s.size()) {
        r.errors.push_back({{file, line, t.col}, "string without its closing '\"'"});
        return;
      }
      t.kind = Tok::String;
      t.text = std::move(v);
      i = j + quoteAt(s, j);
    } else if (std::isdigit(c) || (c == '.' && i + 1 < s.size() && std::isdigit((unsigned char)s[i + 1]))) {
      size_t j = i;
      std::string v;
      while (j < s.size() && std::isdigit((unsigned char)s[j])) v += s[j++];
      bool comma = false;
      if (j < s.size() && (s[j] == '.' || (s[j] == ',' && j + 1 < s.size() && std::isdigit((unsigned char)s[j + 1])))) {
        comma = s[j] == ',';
        t.isInt = false;
        v += '.';
        ++j;
        while (j < s.size() && std::isdigit((unsigned char)s[j])) v += s[j++];
      }
      if (comma) r.decimalCommas.push_back({file, line, t.col});
      t.kind = Tok::Number;
      t.num = std::strtod(v.c_str(), nullptr);
      t.text = s.substr(i, j - i);
      i = j;
    } else if (isLetter(c)) {
      size_t j = i;
      while (j < s.size() && isLetter((unsigned char)s[j])) t.text += (char)std::toupper((unsigned char)s[j++]);
      t.kind = Tok::Word;
      i = j;
    } else {
      t.kind = Tok::Punct;
      t.text = std::string(1, (char)c);
      ++i;
    }
    out.push_back(std::move(t));
  }
}
}  // namespace

LexResult lexFile(std::string_view text, uint32_t file) {
  LexResult r;
  size_t pos = 0;
  uint32_t lineNo = 0;
  bool joinNext = false;  // the line before ended in `~`
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view line = text.substr(pos, nl - pos);
    pos = nl + 1;
    ++lineNo;
    if (lineNo == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line = line.substr(3);  // byte order mark
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
    bool tilde = !line.empty() && line.back() == '~';  // ` ~` ends every line of a block but its last
    if (tilde) line.remove_suffix(1);
    size_t first = line.find_first_not_of(" \t");
    bool continues = joinNext;
    joinNext = tilde;
    if (first == std::string_view::npos) continue;
    size_t cut = commentStart(line);
    std::string_view code = line.substr(0, cut);
    std::string comment;
    if (cut != std::string_view::npos) {
      std::string_view c = line.substr(cut + 1);
      comment = std::string(c.substr(std::min(c.size(), c.find_first_not_of(" \t"))));
    }
    if (!continues && std::isdigit((unsigned char)line[first])) {
      Block b;
      b.line = lineNo;
      size_t j = first;
      while (j < code.size() && std::isdigit((unsigned char)code[j])) ++j;
      b.number = (uint32_t)std::strtoul(std::string(code.substr(first, j - first)).c_str(), nullptr, 10);
      size_t k = code.find_first_not_of(" \t", j);
      if (k != std::string_view::npos && code[k] == '*') {  // `5 * - text`: a comment block
        b.star = true;
        std::string_view c = line.substr(k + 1);
        b.comment = std::string(c.substr(std::min(c.size(), c.find_first_not_of(" \t"))));
      } else {
        if (j < code.size() && code[j] != ' ' && code[j] != '\t')
          r.errors.push_back({{file, lineNo, (uint32_t)j + 1}, "a blank must follow the block number"});
        b.comment = comment;
        lexText(code, j, file, lineNo, b.toks, r);
      }
      r.blocks.push_back(std::move(b));
      continue;
    }
    if (code.find_first_not_of(" \t") == std::string_view::npos) continue;  // a comment line
    if (r.blocks.empty() || r.blocks.back().star) {
      r.errors.push_back({{file, lineNo, (uint32_t)first + 1},
                          r.blocks.empty() ? "text before the first numbered block (BEGIN PGM)" : "a continuation line after a comment block"});
      continue;
    }
    lexText(code, 0, file, lineNo, r.blocks.back().toks, r);
  }
  for (auto &b : r.blocks) {
    Token end;
    end.line = b.toks.empty() ? b.line : b.toks.back().line;
    end.col = b.toks.empty() ? 1 : b.toks.back().col + (uint32_t)b.toks.back().text.size();
    b.toks.push_back(end);
  }
  return r;
}

}  // namespace ncc::hei
