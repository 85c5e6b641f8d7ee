#pragma once
// Reads tokens into the shape every scene file has: a list of module calls
// `name(args) child`, each with its modifiers (`% # ! *`), arguments and
// children. Arguments are OpenSCAD expressions over $t, evaluated as they are
// read (scene_expression.h gives their meaning); OpenSCAD's language beyond
// that (variables, assignments, loops, modules, include) is refused here with
// its location. What the calls mean is decided in parser.cpp.

#include <memory_resource>
#include <string>
#include <string_view>
#include <vector>

#include "capsim/scene/scene.h"
#include "scene/reading/scene_lexer.h"

namespace capsim::scene_file {

// Calls live no longer than the parse that reads them: names and strings view
// the scene text (or, for a string with escapes, its decoded copy in the parse's
// memory), locations point at the parse's file name (see Loc), and every list
// comes from the memory resource given to read_calls. A large scene has
// several lists per statement; a monotonic resource hands them out and frees
// them all at once far more cheaply than the general heap. The constructors
// take that resource so that no list is ever made without it (moving a list
// into one made from another resource would copy it element by element).

// An argument's value, evaluated. `undef` is kept as its own kind: it means "not given".
struct Value {
  enum class Kind { Undef, Bool, Number, String, Vector };
  Value(std::pmr::memory_resource* memory, Loc where) : items(memory), loc(where) {}

  Kind kind = Kind::Undef;
  bool boolean = false;
  double number = 0;        // finite
  std::string_view string;  // decoded
  std::pmr::vector<Value> items;
  Loc loc;  // first token of the value (the '-' of a negative number)
};

struct Argument {
  std::string_view name;  // empty for a positional argument
  Loc name_loc;
  Value value;
};

struct Modifier {
  char symbol = '#';  // one of % # ! *
  Loc loc;
};

// One module instantiation: `%translate([1, 0, 0]) { ... }`.
struct Call {
  explicit Call(std::pmr::memory_resource* memory)
      : modifiers(memory), args(memory), children(memory) {}

  std::string_view name;
  Loc loc;  // of the name
  std::pmr::vector<Modifier> modifiers;
  std::pmr::vector<Argument> args;
  std::pmr::vector<Call> children;
  // Where the children start ('{' or the first token of a single child); only
  // meaningful when has_body.
  Loc body_loc;
  bool has_body = false;  // false for `name(...);`
};

// How deep calls, bare blocks and expressions may nest inside one another:
// each call's children, each bare `{ }` block, each `[ ]`, each `( )` (of a
// group or a function call), each `?` and each `^` is one level. Every
// stage that walks the tree (this reader, the interpreter, the status tree)
// recurses once or a few times per level, so the limit bounds their stack
// use; docs/scene-format.md gives the figures.
inline constexpr int kMaxNestingDepth = 1000;

// The top-level calls of a file in order, their lists drawn from `memory`, which
// must outlive them, their arguments evaluated with $t = t. `end` receives the
// End token's location (for errors about the file as a whole). Throws
// SceneError on any syntax outside the supported subset, on every expression
// OpenSCAD would not evaluate to a value (a wrong type or argument count) or
// that gives a number that is not finite, and on nesting deeper than
// kMaxNestingDepth.
std::pmr::vector<Call> read_calls(const Tokens& tokens,
                                  std::pmr::memory_resource* memory, Loc* end, double t = 0);

}  // namespace capsim::scene_file
