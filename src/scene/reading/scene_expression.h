#pragma once
// What OpenSCAD 2021.01's operators and built-in functions do to values, for
// the expressions of scene files (the reader in scene_syntax.cpp parses them
// and calls these as it goes). Where OpenSCAD would give undef with a warning
// (a wrong type, a wrong argument count), these throw a SceneError at the
// operator, the function or the argument at fault instead.

#include <memory_resource>
#include <span>
#include <string_view>

#include "scene/reading/scene_syntax.h"

namespace capsim::scene_file {

enum class BinaryOp {
  Or, And,                                    // || &&
  Equal, NotEqual,                            // == !=
  Less, LessEqual, Greater, GreaterEqual,     // < <= > >=
  Plus, Minus,                                // + -
  Times, Divide, Modulo,                      // * / %
  Power                                       // ^
};

// OpenSCAD's truth of a value: false for undef, false, 0, "" and [].
bool truthy(const Value& v);

// `a op b` for every op but || and && (the reader evaluates those itself, as
// they skip their right side). The result's location is a's. Numbers may
// become infinite or NaN here; the reader refuses them only where a value is
// used (arguments).
Value apply_binary(BinaryOp op, const Value& a, const Value& b, const Token& op_token,
                   std::pmr::memory_resource* memory);

// -v for a number or a vector of them (recursively).
Value negate(const Value& v, const Token& op_token, std::pmr::memory_resource* memory);

// The built-in function `name` applied to `args`; `call` is the function's
// name token. Precondition: function_arity(name) is known.
Value call_function(const Token& call, std::span<const Value> args,
                    std::pmr::memory_resource* memory);

// How many arguments a built-in function takes, or {0, -1} when `name` is
// not one; max = -1 means any number.
struct Arity {
  int min = 0;
  int max = -1;
  bool known() const { return !(min == 0 && max == -1); }
};
Arity function_arity(std::string_view name);

// The names of the built-in functions, for error messages.
std::string_view function_names();

// OpenSCAD 2021.01's trigonometry in degrees (its degree_trig.cc): exact at
// multiples of 30 and 45 degrees, and the inverse functions exact at whole
// degrees.
double sin_degrees(double x);
double cos_degrees(double x);
double tan_degrees(double x);
double asin_degrees(double x);
double acos_degrees(double x);
double atan_degrees(double x);
double atan2_degrees(double y, double x);

}  // namespace capsim::scene_file
