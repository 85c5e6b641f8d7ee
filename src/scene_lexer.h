#pragma once
// Splits a scene file into tokens, each carrying its file:line:col. Only the
// token shapes of OpenSCAD's language are recognised; what they mean is the
// syntax reader's business (scene_syntax.h).

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "capsim/scene.h"

namespace capsim::scene_file {

enum class TokenKind { Identifier, Number, String, Symbol, End };

struct Token {
  TokenKind kind = TokenKind::End;
  std::string text;   // identifier, decoded string, symbol ("(", "==", ...) or number as written
  double number = 0;  // for Number: the value, always finite
  SourceLoc loc;
};

// The whole file as tokens, ending with one End token placed just after the last
// character. Throws SceneError on unterminated strings and comments, stray
// characters, malformed numbers and numbers outside the range of a double.
std::vector<Token> tokenize(std::string_view text, std::shared_ptr<const std::string> file);

// How a token reads in an error message: `'foo'`, `number 1.5`, `end of file`.
std::string describe(const Token& token);

}  // namespace capsim::scene_file
