#include "cli/options/cli_usage.h"

#include "cli/options/option_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace capsim::cli {

std::string shown(const std::string& value) {
  std::string out;
  bool quote = value.empty();
  for (const char c : value) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      out += fmt::format("\\x{:02x}", byte);
    } else {
      quote = quote || c == ' ';
      out += c;
    }
  }
  return quote ? "'" + out + "'" : out;
}

std::string command_name(const CLI::App& app) {
  std::string name = "capsim";
  for (const CLI::App* cmd = &app; !cmd->get_subcommands().empty();) {
    cmd = cmd->get_subcommands().front();
    name += " " + cmd->get_name();
  }
  return name;
}

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// " (did you mean X?)" or "".
std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string near = closest_name(word, candidates);
  return near.empty() ? "" : fmt::format("; did you mean {}?", near);
}

std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

std::vector<std::string> option_names(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::Option* o : cmd.get_options()) {
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
    for (const std::string& n : o->get_snames()) names.push_back("-" + n);
  }
  return names;
}

// The option's long name ("--size") from the start of a CLI11 message
// ("--size: 1 required TEXT missing"); "" if the message starts otherwise.
std::string option_in_message(const std::string& message) {
  const auto colon = message.find(':');
  if (colon == std::string::npos || message.rfind("-", 0) != 0) return "";
  return message.substr(0, colon);
}

// What the option named `name` ("--size") of the command line's innermost
// command accepts, or of the commands around it; "" if none has it.
std::string accepted_by(const CLI::App& app, const std::string& name) {
  std::vector<const CLI::App*> commands{&app};
  while (!commands.back()->get_subcommands().empty()) commands.push_back(commands.back()->get_subcommands().front());
  for (auto cmd = commands.rbegin(); cmd != commands.rend(); ++cmd)
    if (const CLI::Option* option = (*cmd)->get_option_no_throw(name)) return accepted_values(*option);
  return "";
}

std::string with_accepted(const CLI::App& app, const std::string& text, const std::string& option) {
  const std::string accepted = option.empty() ? "" : accepted_by(app, option);
  return accepted.empty() ? text : fmt::format("{} (accepted: {})", text, accepted);
}

std::string describe_extras(const CLI::App& app) {
  const std::vector<CLI::App*> parsed = app.get_subcommands();
  const std::vector<std::string> commands = subcommand_names(app);
  const std::string all_commands = fmt::format("{}", fmt::join(commands, ", "));
  if (parsed.empty()) {
    // Before any command: the first word is a misspelt command or an option
    // that belongs after one.
    const std::vector<std::string> extra = app.remaining();
    const std::string first = extra.empty() ? "" : extra.front();
    if (first.rfind("-", 0) == 0)
      return fmt::format("unknown option {} (capsim itself takes only --help and --version; give "
                         "options after the command: {})", shown(first), all_commands);
    return fmt::format("unknown command {}{} (accepted: {})", shown(first), suggestion(first, commands),
                       all_commands);
  }
  const CLI::App* innermost = parsed.front();
  std::string path = innermost->get_name();  // "bench modes", as typed after capsim
  while (!innermost->get_subcommands().empty()) {
    innermost = innermost->get_subcommands().front();
    path += " " + innermost->get_name();
  }
  const CLI::App& cmd = *innermost;
  std::vector<std::string> extra = cmd.remaining();
  for (const std::string& e : app.remaining()) extra.push_back(e);  // given before the command
  const std::vector<std::string> inner_commands = subcommand_names(cmd);
  if (!inner_commands.empty() && !extra.empty() && extra.front().rfind("-", 0) != 0)
    return fmt::format("unknown command {}{} (accepted: {})", shown(extra.front()),
                       suggestion(extra.front(), inner_commands), fmt::format("{}", fmt::join(inner_commands, ", ")));
  const auto option =
      std::find_if(extra.begin(), extra.end(), [](const std::string& e) { return e.rfind("-", 0) == 0; });
  const std::vector<std::string> known = option_names(cmd);
  if (option != extra.end() && std::find(known.begin(), known.end(), *option) != known.end())
    return fmt::format("{} is an option of {}: give it after the command's name", *option, cmd.get_name());
  if (option != extra.end())
    return fmt::format("unknown option {}{} (capsim {} --help lists every option)", shown(*option),
                       suggestion(*option, known), path);
  if (cmd.get_name() == "render" || cmd.get_name() == "simulate")
    return fmt::format("unexpected argument {}: {} takes SCENE files and options",
                       shown(extra.empty() ? "" : extra.front()), cmd.get_name());
  return fmt::format("unexpected argument {} (capsim {} --help lists what it takes)",
                     shown(extra.empty() ? "" : extra.front()), path);
}

}  // namespace

std::string closest_name(const std::string& word, const std::vector<std::string>& candidates) {
  if (word.size() >= 2) {
    std::vector<std::string> extending;
    for (const std::string& c : candidates)
      if (c.size() > word.size() && c.rfind(word, 0) == 0) extending.push_back(c);
    if (extending.size() == 1) return extending.front();
  }
  std::string best;
  std::size_t best_distance = word.size() / 3 + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

std::string describe_parse_error(const CLI::App& app, const CLI::ParseError& e) {
  const std::string message = e.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) return describe_extras(app);
  if (const auto* conversion = dynamic_cast<const CLI::ConversionError*>(&e)) {
    // "Could not convert: --primary-only = abc", from a flag given a value.
    const std::string text = conversion->what();
    const auto start = text.find("--"), equals = text.find(" = ");
    if (start != std::string::npos && equals != std::string::npos && equals > start) {
      const std::string name = text.substr(start, equals - start);
      return with_accepted(app, fmt::format("{} {} is not a valid value", name, shown(text.substr(equals + 3))),
                           name);
    }
  }
  const std::string option = option_in_message(message);
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) && !option.empty()) {
    if (message.find("missing") != std::string::npos) return with_accepted(app, option + " needs a value", option);
    if (message.find("received") != std::string::npos)
      return with_accepted(app, option + " is given more than once", option);
  }
  return with_accepted(app, message, option);
}

}  // namespace capsim::cli
