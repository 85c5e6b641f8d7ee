#pragma once
// Splits a scene file into tokens, each carrying its file:line:col. Only the
// token shapes of OpenSCAD's language are recognised; what they mean is the
// syntax reader's business (scene_syntax.h).

#include <cstddef>
#include <memory>
#include <memory_resource>
#include <string>
#include <string_view>
#include <vector>

#include "capsim/scene/scene.h"

namespace capsim::scene_file {

// Where a token, value or call stands in the file being parsed. A parse holds
// one of these per token, value and call, so instead of a SourceLoc (whose
// shared file name costs an atomic reference count on every copy) it points at
// the one shared name the parse owns. It becomes a SourceLoc wherever it leaves
// the parse: in a SceneError or in the Scene.
struct Loc {
  const std::shared_ptr<const std::string>* file = nullptr;
  int line = 0;  // 1-based
  int col = 0;   // 1-based, in bytes

  operator SourceLoc() const { return SourceLoc{file ? *file : nullptr, line, col}; }
};

enum class TokenKind { Identifier, Number, String, Symbol, End };

// Plain data viewing the scanned text, so tokens are copied and stored without
// allocating.
struct Token {
  TokenKind kind = TokenKind::End;
  // Identifier, symbol ("(", "==", ...) or number as written; for String the
  // characters between the quotes with their escapes as written (decode_string
  // gives the value).
  std::string_view text;
  double number = 0;  // for Number: the value, always finite
  Loc loc;
};

// A file's tokens. A large file's take megabytes, so they lie on huge pages
// (capsim/system/huge_pages.h).
using Tokens = std::pmr::vector<Token>;

// The whole file as tokens, ending with one End token placed just after the last
// character. The tokens view `text` and point at `file`: both must outlive them
// and everything read from them. Throws SceneError on unterminated strings and
// comments, stray characters, bad escapes, malformed numbers and numbers outside
// the range of a double.
Tokens tokenize(std::string_view text, const std::shared_ptr<const std::string>& file);

// The value of a String token's text, its escapes (already checked by tokenize)
// decoded.
std::string decode_string(std::string_view raw);

// How a token reads in an error message: `'foo'`, `number 1.5`, `end of file`.
std::string describe(const Token& token);

// Text from the scene (a string's value) in double quotes, as an error message
// can show it whole on any terminal: printable ASCII and well-formed UTF-8 as
// they are, with a backslash before '"' and before a backslash; NUL as \0;
// newline, tab and carriage return as \n, \t and \r; any other control
// character, and every byte that is not part of well-formed UTF-8, as \xNN.
// A text longer than kQuotedBytes shows its first characters up to that many
// bytes, then `... (N bytes in all)` after the closing quote, so that a message
// stays a line however long the scene's string is.
inline constexpr std::size_t kQuotedBytes = 64;
std::string quoted(std::string_view text);

}  // namespace capsim::scene_file
