// Tokenizer for scene files: OpenSCAD's token shapes (identifiers including
// $-variables, numbers, strings, punctuation) plus both comment styles.

#include "scene_lexer.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <system_error>

namespace capsim::scene_file {
namespace {

bool is_ident_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '$';
}
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_ident_char(char c) { return is_ident_start(c) || is_digit(c); }

// Walks the text keeping line and column (1-based; columns count bytes).
class Lexer {
 public:
  Lexer(std::string_view text, std::shared_ptr<const std::string> file)
      : text_(text), file_(std::move(file)) {}

  std::vector<Token> run() {
    // A UTF-8 byte-order mark written by some editors is not part of the scene.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") advance(3);
    std::vector<Token> tokens;
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
  SourceLoc here() const { return SourceLoc{file_, line_, col_}; }
  char peek(size_t ahead = 0) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }
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

  void skip_space_and_comments() {
    while (pos_ < text_.size()) {
      char c = peek();
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
        advance();
      } else if (c == '/' && peek(1) == '/') {
        while (pos_ < text_.size() && peek() != '\n') advance();
      } else if (c == '/' && peek(1) == '*') {
        SourceLoc start = here();
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
      size_t start = pos_;
      while (pos_ < text_.size() && is_ident_char(peek())) advance();
      token.text = std::string(text_.substr(start, pos_ - start));
    } else if (is_digit(c) || (c == '.' && is_digit(peek(1)))) {
      lex_number(token);
    } else if (c == '"') {
      lex_string(token);
    } else {
      lex_symbol(token);
    }
    return token;
  }

  void lex_number(Token& token) {
    token.kind = TokenKind::Number;
    size_t start = pos_;
    while (is_digit(peek())) advance();
    if (peek() == '.') {
      advance();
      while (is_digit(peek())) advance();
    }
    if ((peek() == 'e' || peek() == 'E') &&
        (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
      advance(2);
      while (is_digit(peek())) advance();
    }
    // "1e", "2x" or "1.2.3" are neither a number nor a number and a name.
    while (is_ident_char(peek()) || peek() == '.') advance();
    token.text = std::string(text_.substr(start, pos_ - start));
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

  void lex_string(Token& token) {
    token.kind = TokenKind::String;
    advance();  // opening quote
    for (;;) {
      if (pos_ >= text_.size()) {
        throw SceneError(token.loc, "unterminated string: '\"' has no closing '\"'");
      }
      char c = peek();
      if (c == '"') {
        advance();
        return;
      }
      if (c == '\\') {
        SourceLoc escape_loc = here();
        char e = peek(1);
        switch (e) {
          case '"': token.text += '"'; break;
          case '\\': token.text += '\\'; break;
          case 'n': token.text += '\n'; break;
          case 't': token.text += '\t'; break;
          case 'r': token.text += '\r'; break;
          default:
            if (pos_ + 1 >= text_.size()) {
              throw SceneError(token.loc, "unterminated string: '\"' has no closing '\"'");
            }
            throw SceneError(escape_loc,
                             fmt::format("unsupported escape '\\{}' in string; supported: "
                                         "\\\" \\\\ \\n \\t \\r",
                                         e));
        }
        advance(2);
        continue;
      }
      token.text += c;
      advance();
    }
  }

  void lex_symbol(Token& token) {
    static constexpr std::string_view kSingle = "()[]{},;=+-*/%!#<>?:.^&|~";
    static constexpr std::string_view kDouble[] = {"==", "!=", "<=", ">=", "&&", "||"};
    token.kind = TokenKind::Symbol;
    for (std::string_view op : kDouble) {
      if (text_.substr(pos_, 2) == op) {
        token.text = std::string(op);
        advance(2);
        return;
      }
    }
    char c = peek();
    if (kSingle.find(c) == std::string_view::npos) {
      unsigned char u = static_cast<unsigned char>(c);
      if (u >= 0x21 && u < 0x7f) {
        throw SceneError(token.loc, fmt::format("unexpected character '{}'", c));
      }
      throw SceneError(token.loc, fmt::format("unexpected byte 0x{:02X}", u));
    }
    token.text = std::string(1, c);
    advance();
  }

  std::string_view text_;
  std::shared_ptr<const std::string> file_;
  size_t pos_ = 0;
  int line_ = 1;
  int col_ = 1;
};

}  // namespace

std::vector<Token> tokenize(std::string_view text, std::shared_ptr<const std::string> file) {
  return Lexer(text, std::move(file)).run();
}

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::Identifier: return fmt::format("'{}'", token.text);
    case TokenKind::Number: return fmt::format("number {}", token.text);
    case TokenKind::String: return fmt::format("string \"{}\"", token.text);
    case TokenKind::Symbol: return fmt::format("'{}'", token.text);
    case TokenKind::End: return "end of file";
  }
  return "?";
}

}  // namespace capsim::scene_file
