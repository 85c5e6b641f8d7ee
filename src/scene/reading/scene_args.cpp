// Argument binding and typed reading for scene-file module calls.

#include "scene/reading/scene_args.h"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace capsim::scene_file {
namespace {

constexpr std::string_view kIgnoredSpecials[] = {"$fn", "$fa", "$fs"};

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t above = row[j];
      size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Where an argument is written: its name, or its value if it is positional.
Loc written_at(const Argument& arg) { return arg.name.empty() ? arg.value.loc : arg.name_loc; }

}  // namespace

std::string closest_name(std::string_view name, const std::vector<std::string>& candidates) {
  // A name over twice as long as every candidate is further from each than the
  // limit below allows (the distance is at least the difference in length), so
  // the quadratic distances are skipped: a scene can hold a name of any length.
  size_t longest = 0;
  for (const std::string& c : candidates) longest = std::max(longest, c.size());
  if (name.size() <= 2 * longest) {
    std::string best;
    size_t best_distance = 0;
    for (const std::string& c : candidates) {
      size_t d = edit_distance(name, c);
      if (best.empty() || d < best_distance) {
        best = c;
        best_distance = d;
      }
    }
    // A misspelling changes little relative to the word's length.
    size_t limit = std::max<size_t>(1, std::min(name.size(), best.size()) / 3);
    if (best_distance <= limit) return best;
  }
  // A longer or shorter form of an accepted name ("reflection" for "reflect").
  for (const std::string& c : candidates) {
    size_t common = std::min(name.size(), c.size());
    if (common >= 4 && name.substr(0, common) == std::string_view(c).substr(0, common)) return c;
  }
  return std::string();
}

std::string describe(const Value& value) {
  switch (value.kind) {
    case Value::Kind::Undef: return "undef";
    case Value::Kind::Bool: return "a boolean";
    case Value::Kind::Number: return "a number";
    case Value::Kind::String: return "a string";
    case Value::Kind::Vector:
      return value.items.size() == 1 ? "a vector of 1 element"
                                     : fmt::format("a vector of {} elements", value.items.size());
  }
  return "?";
}

Args::Args(const Call& call, std::initializer_list<std::string_view> positional,
           std::initializer_list<std::string_view> named_only)
    : call_(call) {
  for (std::string_view n : positional) add_param(n);
  for (std::string_view n : named_only) add_param(n);
  for (std::string_view n : kIgnoredSpecials) add_param(n);

  size_t next_positional = 0;
  for (const Argument& arg : call.args) {
    size_t index = param_count_;
    if (arg.name.empty()) {
      if (next_positional >= positional.size()) fail_positional(arg, positional);
      index = next_positional++;
    } else {
      index = index_of(arg.name);
      if (index == param_count_) fail_unknown(arg);
    }
    if (const Argument* first = params_[index].bound) {
      Loc first_loc = written_at(*first);
      throw SceneError(written_at(arg),
                       fmt::format("duplicate argument '{}' for {} (first given at {}:{})",
                                   params_[index].name, call.name, first_loc.line, first_loc.col));
    }
    params_[index].bound = &arg;
  }
  // The specials are the last parameters (added above), so no lookup by name.
  for (size_t i = param_count_ - std::size(kIgnoredSpecials); i < param_count_; ++i) {
    const Argument* special = params_[i].bound;
    if (special && special->value.kind != Value::Kind::Undef &&
        special->value.kind != Value::Kind::Number) {
      fail_type(params_[i].name, "a number");
    }
  }
}

void Args::add_param(std::string_view name) {
  if (param_count_ == kMaxParams) throw std::logic_error("Args: too many parameters");
  params_[param_count_++] = Param{name, nullptr};
}

size_t Args::index_of(std::string_view name) const {
  for (size_t i = 0; i < param_count_; ++i) {
    if (params_[i].name == name) return i;
  }
  return param_count_;
}

void Args::fail_positional(const Argument& arg,
                           std::initializer_list<std::string_view> positional) const {
  std::string list;
  for (std::string_view n : positional) list += (list.empty() ? "" : ", ") + std::string(n);
  throw SceneError(written_at(arg),
                   positional.size() == 0
                       ? fmt::format("{} takes no positional arguments", call_.name)
                       : fmt::format("{} takes at most {} positional argument{} ({})", call_.name,
                                     positional.size(), positional.size() == 1 ? "" : "s", list));
}

void Args::fail_unknown(const Argument& arg) const {
  std::vector<std::string> names = param_names();
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  std::string guess = closest_name(arg.name, names);
  throw SceneError(
      written_at(arg),
      fmt::format("unknown argument '{}' for {}{}; accepted: {}", arg.name, call_.name,
                  guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess), list));
}

std::vector<std::string> Args::param_names() const {
  std::vector<std::string> names;
  for (size_t i = 0; i < param_count_; ++i) names.emplace_back(params_[i].name);
  return names;
}

const Argument* Args::find(std::string_view name) const {
  size_t i = index_of(name);
  if (i == param_count_) return nullptr;
  const Argument* arg = params_[i].bound;
  return arg && arg->value.kind != Value::Kind::Undef ? arg : nullptr;
}

const Value& Args::value(std::string_view name) const { return find(name)->value; }

Loc Args::name_loc(std::string_view name) const { return written_at(*find(name)); }

std::string Args::what(std::string_view name) const {
  return fmt::format("argument '{}' of {}", name, call_.name);
}

void Args::fail_value(std::string_view name, const std::string& message) const {
  throw SceneError(value(name).loc, message);
}

void Args::fail_type(std::string_view name, std::string_view expected) const {
  fail_value(name,
             fmt::format("{} must be {}, got {}", what(name), expected, describe(value(name))));
}

double Args::number(std::string_view name, double fallback) const {
  if (!has(name)) return fallback;
  const Value& v = value(name);
  if (v.kind != Value::Kind::Number) fail_type(name, "a number");
  return v.number;
}

bool Args::boolean(std::string_view name, bool fallback) const {
  if (!has(name)) return fallback;
  const Value& v = value(name);
  if (v.kind != Value::Kind::Bool) fail_type(name, "true or false");
  return v.boolean;
}

glm::dvec3 Args::vec3(std::string_view name, glm::dvec3 fallback) const {
  return has(name) ? numbers(name, 3, 0) : fallback;
}

glm::dvec3 Args::vec2_or_3(std::string_view name, glm::dvec3 fallback, double z) const {
  return has(name) ? numbers(name, 2, z) : fallback;
}

glm::dvec3 Args::number_or_vec3(std::string_view name, glm::dvec3 fallback) const {
  if (!has(name)) return fallback;
  const Value& v = value(name);
  if (v.kind == Value::Kind::Number) return glm::dvec3(v.number);
  if (v.kind != Value::Kind::Vector || v.items.size() != 3) fail_type(name, "a number or a vector of 3 numbers");
  return numbers(name, 3, 0);
}

glm::dvec3 Args::number_or_vec2_or_3(std::string_view name, glm::dvec3 fallback, double z) const {
  if (!has(name)) return fallback;
  const Value& v = value(name);
  if (v.kind == Value::Kind::Number) return glm::dvec3(v.number);
  if (v.kind != Value::Kind::Vector || v.items.size() < 2 || v.items.size() > 3)
    fail_type(name, "a number or a vector of 2 or 3 numbers");
  return numbers(name, 2, z);
}

glm::dvec3 Args::numbers(std::string_view name, std::size_t least, double z) const {
  const Value& v = value(name);
  const std::string expected = least == 3 ? "a vector of 3 numbers" : "a vector of 2 or 3 numbers";
  if (v.kind != Value::Kind::Vector || v.items.size() > 3 || v.items.size() < least) fail_type(name, expected);
  glm::dvec3 out(0, 0, z);
  for (std::size_t i = 0; i < v.items.size(); ++i) {
    const Value& item = v.items[i];
    if (item.kind != Value::Kind::Number) {
      throw SceneError(item.loc, fmt::format("{} must be {}, but element {} is {}", what(name), expected, i + 1,
                                             describe(item)));
    }
    out[static_cast<int>(i)] = item.number;
  }
  return out;
}

}  // namespace capsim::scene_file
