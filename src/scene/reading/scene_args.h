#pragma once
// Binds a call's arguments to a module's parameters the way OpenSCAD does
// (positional ones in order, then by name) and reads them with type checks. Every
// failure is a SceneError at the offending argument: an unknown name lists the
// accepted ones, a wrong type names the expected one.

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "scene/reading/scene_syntax.h"

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
  Loc name_loc(std::string_view name) const;

  double number(std::string_view name, double fallback) const;
  bool boolean(std::string_view name, bool fallback) const;
  glm::dvec3 vec3(std::string_view name, glm::dvec3 fallback) const;
  // A vector of 3 numbers, or of 2 with `z` for the third, as OpenSCAD's
  // translate, scale and mirror read [x, y] (Value::getVec3's default).
  glm::dvec3 vec2_or_3(std::string_view name, glm::dvec3 fallback, double z) const;

  // A number or a vector of 3 numbers: the scalar case repeats the number.
  glm::dvec3 number_or_vec3(std::string_view name, glm::dvec3 fallback) const;
  // A number or a vector of 2 or 3 numbers (the third `z` when 2), as
  // OpenSCAD's scale reads it.
  glm::dvec3 number_or_vec2_or_3(std::string_view name, glm::dvec3 fallback, double z) const;

  // "argument 'r' of sphere"
  std::string what(std::string_view name) const;
  [[noreturn]] void fail_value(std::string_view name, const std::string& message) const;
  [[noreturn]] void fail_type(std::string_view name, std::string_view expected) const;

 private:
  // The argument as a vector of `least` (2 or 3) to 3 numbers, the third
  // `z` when it has 2. Precondition: has(name).
  glm::dvec3 numbers(std::string_view name, std::size_t least, double z) const;
  // One accepted parameter and the argument bound to it, if any.
  struct Param {
    std::string_view name;
    const Argument* bound;
  };
  // More than any module accepts, $fn, $fa and $fs included. A fixed array
  // because an Args is made for every call of a scene.
  static constexpr size_t kMaxParams = 16;

  void add_param(std::string_view name);
  size_t index_of(std::string_view name) const;  // param_count_ when not accepted
  [[noreturn]] void fail_positional(const Argument& arg,
                                    std::initializer_list<std::string_view> positional) const;
  [[noreturn]] void fail_unknown(const Argument& arg) const;
  std::vector<std::string> param_names() const;
  const Argument* find(std::string_view name) const;

  const Call& call_;
  std::array<Param, kMaxParams> params_;  // only the first param_count_ are set
  size_t param_count_ = 0;
};

// "a string", "a vector of 2 elements", ...
std::string describe(const Value& value);

// The accepted name closest to `name` when it is plausibly a misspelling, else "".
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace capsim::scene_file
