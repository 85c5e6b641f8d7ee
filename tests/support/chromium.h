#pragma once
// Headless Chromium for the tests of the HTML pages: find it, load a page,
// and read back the DOM its scripts left.

#include "support/cli_run.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

namespace capsim::testing {

// The Chromium executable on PATH, or "" (CAPSIM_CHROMIUM overrides).
inline std::string find_chromium() {
  if (const char* chosen = std::getenv("CAPSIM_CHROMIUM")) return chosen;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    for (const char* name : {"chromium", "chromium-browser"}) {
      const std::filesystem::path candidate = std::filesystem::path(dir) / name;
      if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
  return "";
}

#define SKIP_WITHOUT_CHROMIUM(chromium)                                                                   \
  if ((chromium).empty())                                                                                 \
  GTEST_SKIP() << "Chromium is not installed (Debian package chromium): the HTML report is not checked " \
                  "in a browser"

// Loads file://page#fragment in headless Chromium, lets its scripts run (with
// up to ten seconds of virtual time for the images to load), and returns the
// DOM they left; with a screenshot path, also takes a screenshot of that size.
// Start-up can be slow on a loaded machine: the launch has two minutes.
inline std::string dump_dom(const std::string& chromium, const TempDir& dir, const std::string& page,
                     const std::string& fragment, const std::string& screenshot = "", int width = 0,
                     int height = 0) {
  const std::string url = "file://" + std::filesystem::absolute(page).string() + fragment;
  std::string command = fmt::format(
      "timeout 120 '{}' --headless --no-sandbox --disable-gpu --no-first-run --no-default-browser-check "
      "--disable-dev-shm-usage --hide-scrollbars --user-data-dir='{}' --virtual-time-budget=10000 --dump-dom",
      chromium, dir / "chromium-profile");
  if (!screenshot.empty())
    command += fmt::format(" --screenshot='{}' --window-size={},{}", screenshot, width, height);
  command += fmt::format(" '{}' >'{}' 2>'{}'", url, dir / "dom.html", dir / "chromium.log");
  const int status = std::system(command.c_str());
  EXPECT_EQ(status, 0) << command << "\n" << read_file(dir / "chromium.log");
  return read_file(dir / "dom.html");
}

}  // namespace capsim::testing
