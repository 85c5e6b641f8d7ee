#include "cli/options/option_checks.h"

#include "cli/options/cli_usage.h"

#include <fmt/core.h>

#include <cctype>
#include <charconv>
#include <limits>
#include <optional>

namespace capsim::cli {

namespace {

// The name accepts() gives the check it attaches.
const std::string kAccepts = "accepts";

// The check accepts() attached to the option, active; CLI11 2.1 hands out an
// option's validators only from a non-const option.
std::optional<CLI::Validator> attached_check(const CLI::Option& option) {
  try {
    const CLI::Validator& check = *const_cast<CLI::Option&>(option).get_validator(kAccepts);
    return check.active(true);
  } catch (const CLI::OptionNotFound&) {
    return std::nullopt;
  }
}

struct Whole {
  bool whole = false;        // text is one whole number, in full
  bool representable = false;  // and within long long
  long long value = 0;
};

Whole parse_whole(const std::string& text) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  return {!text.empty() && end == text.data() + text.size(), ec != std::errc::result_out_of_range, v};
}

std::string whole_problem(const std::string& text, long long lo, long long hi, const std::string& not_whole) {
  const Whole w = parse_whole(text);
  if (!w.whole) return not_whole;
  if (!w.representable || w.value < lo || w.value > hi) return "is out of range";
  return "";
}

std::string number_problem(const std::string& text, double lo, double hi) {
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || end != text.data() + text.size() || ec != std::errc()) return "is not a number";
  if (!(v >= lo && v <= hi)) return "is out of range";
  return "";
}

// The two sides of "AxB" (or "AXB"), if the text has an x.
std::optional<std::pair<std::string, std::string>> pair_sides(const std::string& text) {
  const auto x = text.find_first_of("xX");
  if (x == std::string::npos) return std::nullopt;
  return std::pair{text.substr(0, x), text.substr(x + 1)};
}

std::string pair_problem(const std::string& text, const std::string& form, int max) {
  const auto sides = pair_sides(text);
  if (!sides) return "is not " + form;
  const std::string first = whole_problem(sides->first, 1, max, "is not " + form);
  return !first.empty() ? first : whole_problem(sides->second, 1, max, "is not " + form);
}

// The bytes a size stands for, or the problem with it.
std::uint64_t parse_byte_size(const std::string& text, std::string& problem) {
  std::string digits = text;
  int shift = 0;
  if (!digits.empty()) {
    const std::string units = "KMGT";
    const auto unit = units.find(static_cast<char>(std::toupper(static_cast<unsigned char>(digits.back()))));
    if (unit != std::string::npos) {
      shift = 10 * static_cast<int>(unit + 1);
      digits.pop_back();
    }
  }
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (digits.empty() || end != digits.data() + digits.size()) {
    problem = "is not a size";
  } else if (ec == std::errc::result_out_of_range || v == 0 ||
             v > (std::numeric_limits<std::uint64_t>::max() >> shift)) {
    problem = "is out of range";
  }
  return problem.empty() ? v << shift : 0;
}

}  // namespace

CLI::Option* accepts(CLI::Option* option, const CLI::Validator& check) {
  return option->check(check.active(false), kAccepts);
}

std::string accepted_values(const CLI::Option& option) {
  const std::optional<CLI::Validator> check = attached_check(option);
  return check ? check->get_description() : "";
}

const std::string& checked(const OptionText<>& o) {
  if (const std::optional<CLI::Validator> check = attached_check(*o.option)) {
    const std::string problem = (*check)(o.text);
    if (!problem.empty())
      throw UsageError(fmt::format("{} {} {} (accepted: {})", o.option->get_name(), shown(o.text), problem,
                                   accepted_values(*o.option)));
  }
  return o.text;
}

CLI::Validator whole_number(long long lo, long long hi) {
  return CLI::Validator(
      [lo, hi](std::string& value) { return whole_problem(value, lo, hi, "is not a whole number"); }, "");
}

CLI::Validator decimal_number(double lo, double hi) {
  return CLI::Validator([lo, hi](std::string& value) { return number_problem(value, lo, hi); }, "");
}

CLI::Validator whole_number_pair(const std::string& form, int max) {
  return CLI::Validator([form, max](std::string& value) { return pair_problem(value, form, max); }, "");
}

CLI::Validator byte_size() {
  return CLI::Validator(
      [](std::string& value) {
        std::string problem;
        parse_byte_size(value, problem);
        return problem;
      },
      "");
}

CLI::Validator satisfying(std::function<bool(const std::string&)> accepted, const std::string& problem) {
  return CLI::Validator(
      [accepted = std::move(accepted), problem](std::string& value) { return accepted(value) ? "" : problem; }, "");
}

CLI::Validator refusing(const CLI::Validator& check, const std::string& problem) {
  return CLI::Validator(
      [check, problem](std::string& value) { return check(value).empty() ? std::string() : problem; }, "");
}

int whole_value(const std::string& text) { return static_cast<int>(parse_whole(text).value); }

double number_value(const std::string& text) {
  double v = 0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}

std::pair<int, int> pair_value(const std::string& text) {
  const auto sides = pair_sides(text);
  return {whole_value(sides->first), whole_value(sides->second)};
}

std::uint64_t byte_size_value(const std::string& text) {
  std::string problem;
  return parse_byte_size(text, problem);
}

}  // namespace capsim::cli
