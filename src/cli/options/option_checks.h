#pragma once
// Each option declared once: its names and help (CLI11's add_option), what it
// accepts and the check of its value, a CLI11 Validator attached to it.
//
// The validator's description is what the option accepts, in the words every
// usage error about the option quotes ("--threads abc is not a whole number
// (accepted: 0 to 1024; 0 = all hardware threads)"); its function returns the
// problem with a value ("is not a whole number"), or nothing. The help states
// the same range from the same constants.
//
// CLI11 does not run these validators while it parses: they are attached
// inactive (so the help does not print them either), and checked() runs an
// option's check when its command reads the value. CLI11 would run them, and
// convert the values, as soon as it has read the words, in the order the
// options were registered (the help's), and before it looks for an unknown
// option, a missing required one or --help; capsim reports the words'
// problems first (an unknown option, one given twice, one without its value),
// then the values', in the order each command reads them. And CLI11 reads
// numbers with strtoll and strtold, which take 0x10, 010 (as eight), +5 and
// leading spaces, and CLI::Range lets NaN through; capsim takes plain
// decimals. So values stay text until checked, and the readers at the end of
// this file turn checked text into numbers.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>

namespace capsim::cli {

// An option's text as given (CLI11 writes it; until then, the default) and
// the option registered for it, which holds its check.
template <typename Text = std::string>
struct OptionText {
  Text text;
  CLI::Option* option = nullptr;
};

// Attaches to an option what it accepts: `check`, described in the words its
// messages quote (a description alone, CLI::Validator("a file path"), checks
// nothing). Returns the option.
CLI::Option* accepts(CLI::Option* option, const CLI::Validator& check);

// Registers an option on cmd with its help and what it accepts.
template <typename Text>
CLI::Option* add_option(CLI::App& cmd, const std::string& names, OptionText<Text>& o, const std::string& help,
                        const CLI::Validator& check) {
  o.option = cmd.add_option(names, o.text, help);
  return accepts(o.option, check);
}

// What an option accepts, as its usage errors state it; "" if nothing was
// attached.
std::string accepted_values(const CLI::Option& option);

// The option's text once its check passes; otherwise throws UsageError
// "NAME VALUE PROBLEM (accepted: ...)" with the check's problem.
const std::string& checked(const OptionText<>& o);

// Checks, to be described with what they accept (.description(...)).
//
// A whole number in decimal digits (with '-' for a negative one) from lo to
// hi: "is not a whole number", "is out of range".
CLI::Validator whole_number(long long lo, long long hi);
// A decimal number (std::from_chars's) from lo to hi: "is not a number",
// "is out of range".
CLI::Validator decimal_number(double lo, double hi);
// Two whole numbers from 1 to max written AxB (or AXB), the form `form`
// names ("WxH"): "is not WxH", "is out of range".
CLI::Validator whole_number_pair(const std::string& form, int max);
// A whole number of bytes, or of K, M, G or T (powers of 1024; either case),
// more than 0: "is not a size", "is out of range".
CLI::Validator byte_size();
// A value for which `accepted` holds, else `problem`.
CLI::Validator satisfying(std::function<bool(const std::string&)> accepted, const std::string& problem);
// `check` with `problem` for its own message: for CLI11's validators
// (CLI::IsMember, CLI::ExistingDirectory, and their combinations).
CLI::Validator refusing(const CLI::Validator& check, const std::string& problem);

// Readers of text the matching check accepted.
int whole_value(const std::string& text);
double number_value(const std::string& text);
std::pair<int, int> pair_value(const std::string& text);
std::uint64_t byte_size_value(const std::string& text);

}  // namespace capsim::cli
