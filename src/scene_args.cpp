// Argument binding and typed reading for scene-file module calls.

#include "scene_args.h"

#include <fmt/format.h>

#include <algorithm>

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

}  // namespace

std::string closest_name(std::string_view name, const std::vector<std::string>& candidates) {
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
  for (std::string_view n : positional) names_.emplace_back(n);
  for (std::string_view n : named_only) names_.emplace_back(n);
  for (std::string_view n : kIgnoredSpecials) names_.emplace_back(n);
  bound_.assign(names_.size(), nullptr);

  size_t next_positional = 0;
  for (const Argument& arg : call.args) {
    size_t index = names_.size();
    SourceLoc where = arg.name.empty() ? arg.value.loc : arg.name_loc;
    if (arg.name.empty()) {
      if (next_positional >= positional.size()) {
        std::string list;
        for (std::string_view n : positional) list += (list.empty() ? "" : ", ") + std::string(n);
        throw SceneError(
            where, positional.size() == 0
                       ? fmt::format("{} takes no positional arguments", call.name)
                       : fmt::format("{} takes at most {} positional argument{} ({})", call.name,
                                     positional.size(), positional.size() == 1 ? "" : "s", list));
      }
      index = next_positional++;
    } else {
      index = std::find(names_.begin(), names_.end(), arg.name) - names_.begin();
      if (index == names_.size()) {
        std::string list;
        for (const std::string& n : names_) list += (list.empty() ? "" : ", ") + n;
        std::string guess = closest_name(arg.name, names_);
        throw SceneError(
            where,
            fmt::format("unknown argument '{}' for {}{}; accepted: {}", arg.name, call.name,
                        guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess), list));
      }
    }
    if (const Argument* first = bound_[index]) {
      SourceLoc first_loc = first->name.empty() ? first->value.loc : first->name_loc;
      throw SceneError(where, fmt::format("duplicate argument '{}' for {} (first given at {}:{})",
                                          names_[index], call.name, first_loc.line, first_loc.col));
    }
    bound_[index] = &arg;
  }
  for (std::string_view special : kIgnoredSpecials) {
    if (has(special) && value(special).kind != Value::Kind::Number) fail_type(special, "a number");
  }
}

const Argument* Args::find(std::string_view name) const {
  for (size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) {
      const Argument* arg = bound_[i];
      return arg && arg->value.kind != Value::Kind::Undef ? arg : nullptr;
    }
  }
  return nullptr;
}

const Value& Args::value(std::string_view name) const { return find(name)->value; }

SourceLoc Args::name_loc(std::string_view name) const {
  const Argument* arg = find(name);
  return arg->name.empty() ? arg->value.loc : arg->name_loc;
}

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
  if (!has(name)) return fallback;
  const Value& v = value(name);
  if (v.kind != Value::Kind::Vector || v.items.size() != 3)
    fail_type(name, "a vector of 3 numbers");
  glm::dvec3 out;
  for (int i = 0; i < 3; ++i) {
    const Value& item = v.items[i];
    if (item.kind != Value::Kind::Number) {
      throw SceneError(item.loc,
                       fmt::format("{} must be a vector of 3 numbers, but element {} is {}",
                                   what(name), i + 1, describe(item)));
    }
    out[i] = item.number;
  }
  return out;
}

glm::dvec3 Args::number_or_vec3(std::string_view name, glm::dvec3 fallback) const {
  if (!has(name)) return fallback;
  const Value& v = value(name);
  if (v.kind == Value::Kind::Number) return glm::dvec3(v.number);
  if (v.kind != Value::Kind::Vector || v.items.size() != 3) {
    fail_type(name, "a number or a vector of 3 numbers");
  }
  return vec3(name, fallback);
}

}  // namespace capsim::scene_file
