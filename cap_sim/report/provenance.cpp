#include "report/provenance.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace capsim::sim {

nlohmann::json provenance_json(const Provenance& p) {
  nlohmann::json scenes = nlohmann::json::array();
  for (const InputFile& f : p.scenes) scenes.push_back({{"path", f.path}, {"sha256", f.sha256}});
  return {{"capsim_version", p.version},
          {"argv", p.argv},
          {"scenes", scenes},
          {"profile", {{"given", p.profile}, {"name", p.profile_name}, {"sha256", p.profile_sha256}}},
          {"options", p.options}};
}

namespace {

bool shell_plain(const std::string& word) {
  return !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           std::string_view("-_./=:,+@%").find(c) != std::string_view::npos;
  });
}

std::string shell_word(const std::string& word) {
  if (shell_plain(word)) return word;
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string value_text(const nlohmann::json& v) {
  if (v.is_null() || (v.is_array() && v.empty())) return "none";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_array()) {
    std::vector<std::string> items;
    for (const nlohmann::json& e : v) items.push_back(value_text(e));
    return fmt::format("{}", fmt::join(items, " "));
  }
  return v.dump();
}

}  // namespace

std::string shell_line(const std::vector<std::string>& argv) {
  std::vector<std::string> words;
  for (const std::string& word : argv) words.push_back(shell_word(word));
  return fmt::format("{}", fmt::join(words, " "));
}

std::string options_line(const nlohmann::json& options) {
  std::vector<std::string> pairs;
  for (const auto& [name, value] : options.items()) pairs.push_back(name + " " + value_text(value));
  return fmt::format("{}", fmt::join(pairs, ", "));
}

std::string provenance_text(const Provenance& p) {
  std::string out = fmt::format("\nprovenance: capsim {}\n  {:<8} {}\n", p.version, "command", shell_line(p.argv));
  for (const InputFile& f : p.scenes) out += fmt::format("  {:<8} {} sha256 {}\n", "scene", f.path, f.sha256);
  out += fmt::format("  {:<8} {} (name {}) sha256 {}\n", "profile", p.profile, p.profile_name, p.profile_sha256);
  out += fmt::format("  {:<8} {}\n", "options", options_line(p.options));
  return out;
}

}  // namespace capsim::sim
