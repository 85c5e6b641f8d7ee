#pragma once
// Reads tokens into the shape every scene file has: a list of module calls
// `name(args) child`, each with its modifiers (`% # ! *`), arguments and
// children. Only literal values are allowed as arguments; OpenSCAD's language
// beyond its CSG export (variables, expressions, loops, modules, include) is
// refused here with its location. What the calls mean is decided in parser.cpp.

#include <string>
#include <vector>

#include "capsim/scene.h"
#include "scene_lexer.h"

namespace capsim::scene_file {

// A literal argument value. `undef` is kept as its own kind: it means "not given".
struct Value {
  enum class Kind { Undef, Bool, Number, String, Vector };
  Kind kind = Kind::Undef;
  bool boolean = false;
  double number = 0;  // finite
  std::string string;
  std::vector<Value> items;
  SourceLoc loc;  // first token of the value (the '-' of a negative number)
};

struct Argument {
  std::string name;  // empty for a positional argument
  SourceLoc name_loc;
  Value value;
};

struct Modifier {
  char symbol = '#';  // one of % # ! *
  SourceLoc loc;
};

// One module instantiation: `%translate([1, 0, 0]) { ... }`.
struct Call {
  std::string name;
  SourceLoc loc;  // of the name
  std::vector<Modifier> modifiers;
  std::vector<Argument> args;
  std::vector<Call> children;
  // Where the children start ('{' or the first token of a single child); only
  // meaningful when has_body.
  SourceLoc body_loc;
  bool has_body = false;  // false for `name(...);`
};

// The top-level calls of a file in order. `end` receives the End token's location
// (for errors about the file as a whole). Throws SceneError on any syntax outside
// the supported subset.
std::vector<Call> read_calls(const std::vector<Token>& tokens, SourceLoc* end);

}  // namespace capsim::scene_file
