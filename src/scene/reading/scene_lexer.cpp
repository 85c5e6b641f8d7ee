// Tokenizer for scene files: OpenSCAD's token shapes (identifiers including
// $-variables, numbers, strings, punctuation) plus both comment styles.

#include "scene/reading/scene_lexer.h"

#include "capsim/system/huge_pages.h"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <system_error>

namespace capsim::scene_file {
namespace {

bool is_ident_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '$';
}
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_ident_char(char c) { return is_ident_start(c) || is_digit(c); }
// The escapes decode_string knows: \" \\ \n \t \r.
bool is_supported_escape(char c) {
  return c == '"' || c == '\\' || c == 'n' || c == 't' || c == 'r';
}

constexpr std::string_view kSingleSymbols = "()[]{},;=+-*/%!#<>?:.^&|~";
constexpr std::string_view kDoubleSymbols[] = {"==", "!=", "<=", ">=", "&&", "||"};

// kSingleSymbols indexed by byte: most tokens are symbols, so each costs one lookup.
constexpr std::array<bool, 256> kIsSingleSymbol = [] {
  std::array<bool, 256> table{};
  for (char c : kSingleSymbols) table[static_cast<unsigned char>(c)] = true;
  return table;
}();

bool is_double_symbol(char first, char second) {
  for (std::string_view op : kDoubleSymbols) {
    if (op[0] == first && op[1] == second) return true;
  }
  return false;
}

// The value of `text` when it is a whole number of at most 15 digits, which a
// double holds exactly: the same value from_chars gives, without its cost for
// the most common numbers of scene files.
std::optional<double> exact_whole_number(std::string_view text) {
  if (text.size() > 15) return std::nullopt;
  std::uint64_t value = 0;
  for (char c : text) {
    if (!is_digit(c)) return std::nullopt;
    value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return static_cast<double>(value);
}

// Walks the text keeping line and column (1-based; columns count bytes).
class Lexer {
 public:
  Lexer(std::string_view text, const std::shared_ptr<const std::string>& file)
      : text_(text), file_(&file) {}

  Tokens run() {
    // A UTF-8 byte-order mark written by some editors is not part of the scene.
    if (text_.starts_with("\xEF\xBB\xBF")) advance_on_line(3);
    // A CSG export has about one token per two bytes; reserving that up front
    // spares a large scene the copies (and fresh pages) of repeated growth.
    Tokens tokens(huge_page_resource());
    tokens.reserve(text_.size() / 2 + 2);
    for (;;) {
      skip_space_and_comments();
      if (pos_ >= text_.size()) break;
      tokens.push_back(next());
    }
    Token end;
    end.kind = TokenKind::End;
    end.loc = here();
    tokens.push_back(end);
    return tokens;
  }

 private:
  Loc here() const { return Loc{file_, line_, col_}; }
  // The character at `index`, '\0' past the end.
  char at(size_t index) const { return index < text_.size() ? text_[index] : '\0'; }
  char peek(size_t ahead = 0) const { return at(pos_ + ahead); }
  void advance(size_t n = 1) {
    for (size_t i = 0; i < n && pos_ < text_.size(); ++i, ++pos_) {
      if (text_[pos_] == '\n') {
        ++line_;
        col_ = 1;
      } else {
        ++col_;
      }
    }
  }
  // advance(n) for the common case of n characters known to hold no newline.
  void advance_on_line(size_t n) {
    pos_ += n;
    col_ += static_cast<int>(n);
  }
  // The next `length` characters as a token's text, consumed.
  std::string_view take_on_line(size_t length) {
    std::string_view taken = text_.substr(pos_, length);
    advance_on_line(length);
    return taken;
  }

  void skip_space_and_comments() {
    while (pos_ < text_.size()) {
      char c = peek();
      if (c == '\n') {
        advance();
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        advance_on_line(1);
      } else if (c == '/' && peek(1) == '/') {
        size_t newline = text_.find('\n', pos_);
        advance_on_line((newline == std::string_view::npos ? text_.size() : newline) - pos_);
      } else if (c == '/' && peek(1) == '*') {
        Loc start = here();
        advance(2);
        while (pos_ < text_.size() && !(peek() == '*' && peek(1) == '/')) advance();
        if (pos_ >= text_.size())
          throw SceneError(start, "unterminated comment: '/*' has no closing '*/'");
        advance(2);
      } else {
        return;
      }
    }
  }

  Token next() {
    Token token;
    token.loc = here();
    char c = peek();
    if (is_ident_start(c)) {
      token.kind = TokenKind::Identifier;
      size_t end = pos_ + 1;
      while (is_ident_char(at(end))) ++end;
      token.text = take_on_line(end - pos_);
    } else if (is_digit(c) || (c == '.' && is_digit(peek(1)))) {
      lex_number(token);
    } else if (c == '"') {
      lex_string(token);
    } else {
      lex_symbol(token);
    }
    return token;
  }

  // Where the number starting at pos_ ends; numbers never span lines.
  size_t number_end() const {
    size_t end = pos_;
    while (is_digit(at(end))) ++end;
    if (at(end) == '.') {
      ++end;
      while (is_digit(at(end))) ++end;
    }
    char e = at(end), sign = at(end + 1);
    if ((e == 'e' || e == 'E') &&
        (is_digit(sign) || ((sign == '+' || sign == '-') && is_digit(at(end + 2))))) {
      end += 2;
      while (is_digit(at(end))) ++end;
    }
    // "1e", "2x" or "1.2.3" are neither a number nor a number and a name.
    while (is_ident_char(at(end)) || at(end) == '.') ++end;
    return end;
  }

  void lex_number(Token& token) {
    token.kind = TokenKind::Number;
    token.text = take_on_line(number_end() - pos_);
    if (std::optional<double> whole = exact_whole_number(token.text)) {
      token.number = *whole;
      return;
    }
    const char* first = token.text.data();
    const char* last = first + token.text.size();
    auto [end, ec] = std::from_chars(first, last, token.number);
    if (end != last || (ec != std::errc() && ec != std::errc::result_out_of_range)) {
      throw SceneError(token.loc, fmt::format("malformed number '{}'", token.text));
    }
    if (ec == std::errc::result_out_of_range || !std::isfinite(token.number)) {
      throw SceneError(token.loc,
                       fmt::format("number '{}' is out of the range of a double", token.text));
    }
  }

  // Checks the string's escapes; its text stays as written (decode_string).
  void lex_string(Token& token) {
    token.kind = TokenKind::String;
    advance();  // opening quote
    size_t start = pos_;
    for (;;) {
      if (pos_ >= text_.size()) {
        throw SceneError(token.loc, "unterminated string: '\"' has no closing '\"'");
      }
      char c = peek();
      if (c == '"') {
        token.text = text_.substr(start, pos_ - start);
        advance();
        return;
      }
      if (c == '\\') {
        char e = peek(1);
        if (!is_supported_escape(e)) {
          if (pos_ + 1 >= text_.size()) {
            throw SceneError(token.loc, "unterminated string: '\"' has no closing '\"'");
          }
          const auto byte = static_cast<unsigned char>(e);
          throw SceneError(
              here(), fmt::format("unsupported escape {} in string; supported: "
                                  "\\\" \\\\ \\n \\t \\r",
                                  byte >= 0x21 && byte < 0x7f
                                      ? fmt::format("'\\{}'", e)
                                      : fmt::format("'\\' followed by byte 0x{:02X}", byte)));
        }
        advance(2);
        continue;
      }
      advance();
    }
  }

  void lex_symbol(Token& token) {
    token.kind = TokenKind::Symbol;
    char c = peek();
    if (is_double_symbol(c, peek(1))) {
      token.text = take_on_line(2);
      return;
    }
    if (!kIsSingleSymbol[static_cast<unsigned char>(c)]) {
      unsigned char u = static_cast<unsigned char>(c);
      if (u >= 0x21 && u < 0x7f) {
        throw SceneError(token.loc, fmt::format("unexpected character '{}'", c));
      }
      throw SceneError(token.loc, fmt::format("unexpected byte 0x{:02X}", u));
    }
    token.text = take_on_line(1);
  }

  std::string_view text_;
  const std::shared_ptr<const std::string>* file_;
  size_t pos_ = 0;
  int line_ = 1;
  int col_ = 1;
};

}  // namespace

Tokens tokenize(std::string_view text, const std::shared_ptr<const std::string>& file) {
  return Lexer(text, file).run();
}

std::string decode_string(std::string_view raw) {
  std::string decoded;
  decoded.reserve(raw.size());
  for (size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] != '\\' || i + 1 == raw.size()) {
      decoded += raw[i];
      continue;
    }
    switch (raw[++i]) {
      case 'n': decoded += '\n'; break;
      case 't': decoded += '\t'; break;
      case 'r': decoded += '\r'; break;
      default: decoded += raw[i]; break;  // '"' or '\\'
    }
  }
  return decoded;
}

namespace {

// The length of the well-formed UTF-8 sequence of two or more bytes starting at
// text[i] (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF),
// or 0 if there is none.
size_t utf8_sequence_length(std::string_view text, size_t i) {
  const auto byte = [&](size_t k) {
    return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u;
  };
  const auto continuation = [&](size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) {
    return byte(k) >= lo && byte(k) <= hi;
  };
  const unsigned lead = byte(i);
  if (lead >= 0xC2 && lead <= 0xDF) return continuation(i + 1) ? 2 : 0;
  if (lead >= 0xE0 && lead <= 0xEF) {
    const unsigned lo = lead == 0xE0 ? 0xA0 : 0x80, hi = lead == 0xED ? 0x9F : 0xBF;
    return continuation(i + 1, lo, hi) && continuation(i + 2) ? 3 : 0;
  }
  if (lead >= 0xF0 && lead <= 0xF4) {
    const unsigned lo = lead == 0xF0 ? 0x90 : 0x80, hi = lead == 0xF4 ? 0x8F : 0xBF;
    return continuation(i + 1, lo, hi) && continuation(i + 2) && continuation(i + 3) ? 4 : 0;
  }
  return 0;
}

}  // namespace

std::string quoted(std::string_view text) {
  std::string out = "\"";
  size_t i = 0;
  while (i < text.size() && i < kQuotedBytes) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      if (size_t n = utf8_sequence_length(text, i)) {
        out.append(text.substr(i, n));
        i += n;
      } else {
        out += fmt::format("\\x{:02X}", c);
        ++i;
      }
      continue;
    }
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\0': out += "\\0"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (c < 0x20 || c == 0x7f) {
          out += fmt::format("\\x{:02X}", c);
        } else {
          out += static_cast<char>(c);
        }
    }
    ++i;
  }
  out += '"';
  if (i < text.size()) out += fmt::format("... ({} bytes in all)", text.size());
  return out;
}

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::Identifier: return fmt::format("'{}'", token.text);
    case TokenKind::Number: return fmt::format("number {}", token.text);
    case TokenKind::String: return "string " + quoted(decode_string(token.text));
    case TokenKind::Symbol: return fmt::format("'{}'", token.text);
    case TokenKind::End: return "end of file";
  }
  return "?";
}

}  // namespace capsim::scene_file
