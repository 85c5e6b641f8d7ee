#pragma once
// Binds a call's arguments to a module's parameters the way OpenSCAD does
// (positional ones in order, then by name) and reads them with type checks. Every
// failure is a SceneError at the offending argument: an unknown name lists the
// accepted ones, a wrong type names the expected one.

#include <glm/glm.hpp>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "scene_syntax.h"

namespace capsim::scene_file {

class Args {
 public:
  // `positional`: parameter names positional arguments fill, in order;
  // `named_only`: further names accepted only as name=value. $fn, $fa and $fs are
  // accepted by every module and ignored (they must still be numbers).
  Args(const Call& call, std::initializer_list<std::string_view> positional,
       std::initializer_list<std::string_view> named_only = {});

  // Given with a value other than undef (undef means "not given", as in OpenSCAD).
  bool has(std::string_view name) const { return find(name) != nullptr; }
  // Precondition: has(name).
  const Value& value(std::string_view name) const;
  // Where the argument's name is written (its value's location if positional).
  SourceLoc name_loc(std::string_view name) const;

  double number(std::string_view name, double fallback) const;
  bool boolean(std::string_view name, bool fallback) const;
  glm::dvec3 vec3(std::string_view name, glm::dvec3 fallback) const;

  // A number or a vector of 3 numbers: the scalar case repeats the number.
  glm::dvec3 number_or_vec3(std::string_view name, glm::dvec3 fallback) const;

  // "argument 'r' of sphere"
  std::string what(std::string_view name) const;
  [[noreturn]] void fail_value(std::string_view name, const std::string& message) const;
  [[noreturn]] void fail_type(std::string_view name, std::string_view expected) const;

 private:
  const Argument* find(std::string_view name) const;

  const Call& call_;
  std::vector<const Argument*> bound_;  // parallel to names_
  std::vector<std::string> names_;
};

// "a string", "a vector of 2 elements", ...
std::string describe(const Value& value);

// The accepted name closest to `name` when it is plausibly a misspelling, else "".
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace capsim::scene_file
