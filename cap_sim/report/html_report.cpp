#include "report/html_report.h"

#include "machine/statistics.h"

#include "report/heatmap.h"
#include "report/html_assets.h"
#include "report/page_data.h"
#include "report/sim_report.h"

#include "capsim/image/image_io.h"

#include <fmt/core.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace capsim::sim {

namespace {

// A table cell in seconds with the exact cycles on hover.
std::string seconds_cell(Cycles c, std::uint64_t hz) {
  return fmt::format("<td title=\"{} cycles\">{:.3f}</td>", grouped(c.count()), c.seconds(hz));
}

// The screen's 8-bit sRGB colours, whichever format the run kept.
std::vector<unsigned char> screen_rgb8(const FrameScreen& s) {
  return s.screen_srgb8.empty() ? srgb8_pixels(s.screen) : s.screen_srgb8;
}

// How many times a screen is enlarged on the page so that small screens are
// not postage stamps (shown with square pixels).
int display_scale(int width, int height) { return std::max(1, 512 / std::max(width, height)); }

std::string img(const std::string& id, const std::string& cls, const std::vector<unsigned char>& png, int width,
                int height, int scale, const std::string& alt) {
  return fmt::format(
      "<img id=\"{}\" class=\"{}\" src=\"{}\" width=\"{}\" height=\"{}\" style=\"width:{}px\" alt=\"{}\">", id, cls,
      png_data_uri(png), width, height, width * scale, html_escape(alt));
}

// When a frame's pixels appeared, first and last.
std::pair<std::uint64_t, std::uint64_t> completion_range(const FrameScreen& s) {
  const auto [lo, hi] = std::minmax_element(s.completion_cycles.begin(), s.completion_cycles.end());
  return {*lo, *hi};
}

const Provenance* provenance_of(const RunFacts& facts) {
  return facts.provenance ? &*facts.provenance : nullptr;
}

std::string header_section(const SimulationResult& r, const RunFacts& facts) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const bool sequence = r.screens.size() > 1;
  std::string nav =
      "<a href=\"#run\">Run</a> <a href=\"#screen\">Screen</a> <a href=\"#cells\">Cells</a> "
      "<a href=\"#timeline-section\">Timeline</a> <a href=\"#breakdown\">Time by process</a>";
  if (r.config.aa.depth > 0) nav += " <a href=\"#antialiasing\">Antialiasing</a>";
  if (sequence) nav += " <a href=\"#sequence\">Frames</a>";
  return fmt::format(
      "<header>\n<h1>CAP simulation of <span class=\"scene\">{}</span></h1>\n"
      "<p class=\"lead\">{} cells in {} mode, profile {}, {}x{} pixels{}: {} <strong id=\"lead-time\">{:.3f} s"
      "</strong> of simulated time{}.</p>\n<nav>{}</nav>\n</header>\n",
      html_escape(run_name(facts.scenes, r.screens.size())), to_string(r.config.cells), to_string(r.config.mode),
      html_escape(r.config.profile.name), r.width, r.height,
      sequence ? fmt::format(", {} frames", r.screens.size()) : "", sequence ? "all the frames took" : "the frame took",
      r.frame.seconds(hz),
      sequence ? fmt::format(", {:.3f} s per frame (mean)", sequence_time(r).frame_seconds) : std::string(), nav);
}

// The provenance's block as rows of the run's table: the command as typed,
// each input's SHA-256 and the options' effective values.
std::string provenance_rows(const Provenance& p) {
  auto row = [](const std::string& name, const std::string& value) {
    return fmt::format("<tr class=\"provenance\"><th>{}</th><td>{}</td></tr>\n", name, value);
  };
  std::string rows = row("Command as typed", "<code>" + html_escape(shell_line(p.argv)) + "</code>");
  for (const InputFile& f : p.scenes)
    rows += row("SHA-256 of " + html_escape(f.path), "<code>" + f.sha256 + "</code>");
  rows += row("SHA-256 of profile " + html_escape(p.profile),
              fmt::format("<code>{}</code> (name {})", p.profile_sha256, html_escape(p.profile_name)));
  rows += row("Options", html_escape(options_line(p.options)));
  return rows;
}

std::string run_section(const SimulationResult& r, const RunFacts& facts) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  auto row = [](const char* name, const std::string& value, const char* id = nullptr) {
    return fmt::format("<tr><th>{}</th><td{}>{}</td></tr>\n", name, id ? fmt::format(" id=\"{}\"", id) : "", value);
  };
  std::string rows;
  rows += row(facts.scenes.size() > 1 ? "Scenes" : "Scene",
              html_escape(fmt::format("{}", fmt::join(facts.scenes, " "))));
  rows += row("Command", "<code>" + html_escape(facts.command) + "</code>");
  rows += row("Profile", fmt::format("{}, clock {} Hz", html_escape(r.config.profile.name), grouped(hz)));
  rows += row("Cells", fmt::format("{} ({} cells)", to_string(r.config.cells), r.config.cells.cell_count()));
  rows += row("Pixel mode", to_string(r.config.mode));
  rows += row("Screen", fmt::format("{}x{} pixels", r.width, r.height));
  if (r.screens.size() > 1)
    rows += row("Frames", r.config.frame_average
                              ? fmt::format("{}, frame averaged in groups of {}", r.screens.size(),
                                            r.config.cells.cell_count())
                              : fmt::format("{}, one at a time", r.screens.size()));
  rows += row("Antialiasing", r.config.aa.depth > 0
                                  ? fmt::format("depth {}, threshold {}, {} links", r.config.aa.depth,
                                                r.config.aa.threshold, to_string(r.config.profile.link.topology))
                                  : std::string("none (one sample at each pixel centre)"));
  if (r.screens.size() > 1)
    rows += row("Time", fmt::format("{} ({} cycles in all)", sequence_time_text(r), grouped(r.frame.count())),
                "frame-time");
  else
    rows += row("Frame time", fmt::format("{:.3f} s ({} cycles)", r.frame.seconds(hz), grouped(r.frame.count())),
                "frame-time");
  rows += row("Data broadcast",
              fmt::format("program {} B, scene {} B, voxel data {} B", grouped(r.config.profile.program_bytes),
                          grouped(r.footprint.scene_bytes()), grouped(r.footprint.voxel_bytes())));
  rows += row("Events simulated", grouped(r.events));
  rows += row("Host wall time",
              facts.host_seconds >= 0 ? fmt::format("{:.3f} s", facts.host_seconds) : std::string("not measured"),
              "host-time");
  rows += row("capsim", html_escape(facts.version));
  if (facts.provenance) rows += provenance_rows(*facts.provenance);
  return "<section id=\"run\">\n<h2>The run</h2>\n<table class=\"facts\">\n" + rows + "</table>\n</section>\n";
}

// How the screen fills in the run's pixel mode.
std::string filling(const MachineConfig& config) {
  const CellGrid g = config.cells;
  if (g.cell_count() == 1) return "With one cell the screen fills in its tracing order, row by row.";
  switch (config.mode) {
    case PixelMode::Block:
      return fmt::format("In block mode each of the {} cells fills its own rectangle, all at once, row by row.",
                         g.cell_count());
    case PixelMode::Line:
      return fmt::format("In line mode each cell owns one row in every {}, so the cells fill interleaved rows and "
                         "the screen sweeps down in bands.",
                         g.cell_count());
    case PixelMode::Dot:
      return fmt::format("In dot mode each cell owns one pixel of every {}x{} square, so the whole screen fills at "
                         "once, dot by dot, sweeping down.",
                         g.rows, g.cols);
  }
  return "";
}

std::string screen_section(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const int scale = display_scale(r.width, r.height);
  const bool sequence = r.screens.size() > 1;
  // Each column as wide as a screen shown at its scale, and at least as wide
  // as the player's controls need.
  const int column = std::max(360, r.width * scale);
  std::string screens, maps;
  for (std::size_t f = 0; f < r.screens.size(); ++f) {
    const FrameScreen& s = r.screens[f];
    const std::string frame = sequence ? fmt::format("Frame {}: ", f) : "";
    screens += fmt::format(
        "<figure class=\"frame\" data-frame=\"{}\">{}<figcaption>{}the screen as the video bus showed it"
        "</figcaption></figure>\n",
        f, img(fmt::format("screen-{}", f), "screen", encode_png_rgb8(r.width, r.height, screen_rgb8(s)), r.width,
               r.height, scale, frame + "the screen"),
        frame);
    const auto [first, last] = completion_range(s);
    const RgbImage map = render_completion_map(s.completion_cycles, r.width, r.height, Cycles(first), Cycles(last));
    maps += fmt::format(
        "<figure class=\"frame\" data-frame=\"{}\">{}<figcaption>{}<span class=\"legend\"><span>{:.3f} s</span>"
        "<span class=\"viridis bar\"></span><span>{:.3f} s</span></span></figcaption></figure>\n",
        f,
        img(fmt::format("completion-map-{}", f), "completion-map", encode_png_rgb8(map.width, map.height, map.rgb),
            map.width, map.height, scale, frame + "when each pixel appeared"),
        frame, Cycles(first).seconds(hz), Cycles(last).seconds(hz));
  }
  return fmt::format(
      "<section id=\"screen\">\n<h2>The screen</h2>\n"
      "<p>Each cell traces the pixels its window controller shows, in the order of its video memory, and each "
      "pixel is on the screen from the cycle its tracing{} ends. The player shows the screen at any moment of "
      "simulated time. {}</p>\n<div class=\"side-by-side\">\n<div style=\"width:{}px\">\n"
      "<div id=\"player\" class=\"player\"></div>\n<noscript><p class=\"note\">The player needs JavaScript; "
      "here is the finished screen.</p></noscript>\n<div id=\"screens\" class=\"frames\">\n{}</div>\n</div>\n"
      "<div style=\"width:{}px\">\n<h3>When each pixel appeared</h3>\n"
      "<p class=\"explain\">The cycle each pixel reached the screen, "
      "from the first (dark blue) to the last (yellow); hover for a pixel's time and cell.</p>\n"
      "<div id=\"completion-maps\" class=\"frames\">\n{}</div>\n</div>\n</div>\n</section>\n",
      r.config.aa.depth > 0 ? " (antialiased, its subdivision)" : "", filling(r.config), column, screens, column,
      maps);
}

std::string spread_table(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const LoadSpread s = load_spread(r);
  return fmt::format(
      "<table id=\"spread\" class=\"spread\">\n<caption>Load spread (Table 4-4's form)</caption>\n"
      "<tr><th>Max</th><td title=\"{} cycles\">{:.3f} s</td></tr>\n"
      "<tr><th>Min</th><td title=\"{} cycles\">{:.3f} s</td></tr>\n"
      "<tr><th>d = (Max &minus; Min) / Max</th><td>{:.2f} %</td></tr>\n</table>\n",
      grouped(s.max_finish.count()), s.max_finish.seconds(hz), grouped(s.min_finish.count()),
      s.min_finish.seconds(hz), s.deviation_percent);
}

std::string cell_table(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const bool aa = r.config.aa.depth > 0;
  // Every cell statistic the run kept, cycles shown in seconds.
  auto kept = [&](const Statistic<CellReport>& s) {
    return statistic_kept(s.scope, aa, r.config.balance.scheme, r.config.voxel_generation == VoxelGeneration::Cells);
  };
  std::string head = "<th data-key=\"cell\">Cell</th><th data-key=\"row\">Row</th><th data-key=\"col\">Col</th>";
  for (const auto& s : kCellStatistics)
    if (kept(s))
      head += fmt::format("<th data-key=\"{}\">{}{}</th>", s.json_key(), s.title,
                          s.unit == StatisticUnit::Cycles ? " s" : "");
  std::string body;
  for (const CellReport& c : r.cells) {
    body += fmt::format("<tr data-cell=\"{}\"><td>{}</td><td>{}</td><td>{}</td>", c.id, c.id, c.position.row,
                        c.position.col);
    for (const auto& s : kCellStatistics)
      if (kept(s))
        body += s.unit == StatisticUnit::Cycles ? seconds_cell(Cycles(s.value(c)), hz)
                                                : fmt::format("<td>{}</td>", grouped(s.value(c)));
    body += "</tr>\n";
  }
  return fmt::format(
      "<div class=\"table-box\"><table id=\"cell-table\" class=\"numbers\">\n<caption>Per cell: busy is tracing, "
      "comm receiving the broadcasts and sending (waits for the bus{} included), finish the cycle its "
      "&ldquo;done&rdquo; reached the host, idle the rest{}</caption>\n<thead><tr>{}</tr></thead>\n<tbody>\n{}"
      "</tbody>\n</table></div>\n",
      aa ? " or a link" : "",
      aa ? "; antialiased, each phase from its start to its end, the exchange with its waits" : "", head, body);
}

std::string cells_section(const SimulationResult& r) {
  const RgbImage heat = render_heatmap(r);
  return fmt::format(
      "<section id=\"cells\">\n<h2>The cells</h2>\n<div class=\"side-by-side\">\n"
      "<div id=\"cell-map\" class=\"cell-map\"><noscript>{}<p class=\"note\">Busy time per cell, "
      "least (dark blue) to most (yellow).</p></noscript></div>\n{}</div>\n{}</section>\n",
      img("cell-heatmap", "cell-heatmap", encode_png_rgb8(heat.width, heat.height, heat.rgb), heat.width,
          heat.height, 1, "busy time per cell"),
      spread_table(r), cell_table(r));
}

std::string breakdown_section(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const double total = r.breakdown.total().seconds(hz);
  std::string rows;
  for (const CostCategoryInfo& process : kCostCategoryTable) {
    const Cycles c = r.breakdown[process.category];
    const double percent = total > 0 ? 100.0 * c.seconds(hz) / total : 0.0;
    rows += fmt::format(
        "<tr data-process=\"{}\"><th>{}</th><td title=\"{} cycles\">{:.3f} s</td><td>{:.1f} %</td>"
        "<td class=\"bar-cell\"><span class=\"bar\" style=\"width:{:.1f}%\"></span></td></tr>\n",
        process.json_key, process.name, grouped(c.count()), c.seconds(hz), percent, percent);
  }
  return fmt::format(
      "<section id=\"breakdown\">\n<h2>Time by process</h2>\n<table id=\"breakdown-table\" class=\"breakdown\">\n"
      "<caption>Every cell's tracing and the host's voxel generation, by process (Table 4-3's form)</caption>\n"
      "{}<tr class=\"total\"><th>total</th><td title=\"{} cycles\">{:.3f} s</td><td></td><td></td></tr>\n</table>\n"
      "</section>\n",
      rows, grouped(r.breakdown.total().count()), total);
}

std::string timeline_section() {
  return "<section id=\"timeline-section\">\n<h2>Timeline</h2>\n"
         "<p>Every span of the trace: the host, the command bus, each cell and, antialiased, each link that "
         "carried corners. Scroll to zoom, drag to pan, double-click to see it all; hover for a span's cycles. "
         "The saved trace opens in Perfetto (ui.perfetto.dev) or chrome://tracing.</p>\n"
         "<div class=\"toolbar\"><button type=\"button\" id=\"save-trace\" hidden>Save the trace JSON</button> "
         "<button type=\"button\" id=\"save-report\" hidden>Save the report JSON</button></div>\n"
         "<div id=\"timeline\" class=\"timeline\"></div>\n<noscript><p class=\"note\">The timeline needs "
         "JavaScript. The trace is in this file, in the element with id trace-data.</p></noscript>\n</section>\n";
}

std::string antialiasing_section(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const LinkTotals t = link_totals(r);
  std::string link_heads;  // every link statistic, cycles as cycles
  for (const auto& s : kLinkStatistics) link_heads += fmt::format("<th>{}</th>", s.title);
  std::string links;
  for (const LinkTraffic& l : r.links) {
    const CellPosition p = r.config.cells.position(l.cell);
    links += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td>", p.row, p.col, to_string(l.direction));
    for (const auto& s : kLinkStatistics) links += fmt::format("<td>{}</td>", grouped(s.value(l)));
    links += "</tr>\n";
  }
  return fmt::format(
      "<section id=\"antialiasing\">\n<h2>Antialiasing</h2>\n<p>Depth {}, threshold {}: {}; the table of cells "
      "gives each phase.</p>\n"
      "<table id=\"link-totals\" class=\"facts\">\n<caption>Link traffic</caption>\n"
      "<tr><th>Messages</th><td>{}</td></tr>\n<tr><th>Bytes</th><td>{}</td></tr>\n"
      "<tr><th>Hops</th><td>{} (at most {} for one message)</td></tr>\n"
      "<tr><th>Busiest link</th><td>{} cycles ({:.4f} s)</td></tr>\n"
      "<tr><th>Longest wait for a link</th><td>{} cycles</td></tr>\n</table>\n"
      "<div id=\"link-map\" class=\"link-map\"></div>\n"
      "<details><summary>Every link that carried corners ({})</summary>\n<div class=\"table-box\">"
      "<table id=\"link-table\" class=\"numbers\">\n<thead><tr><th>Row</th><th>Col</th><th>Direction</th>"
      "{}</tr></thead>\n<tbody>\n{}"
      "</tbody>\n</table></div>\n</details>\n</section>\n",
      r.config.aa.depth, r.config.aa.threshold,
      r.config.balance.on_demand()
          ? std::string("each tile traces every corner of its pixels (those on its border again where a "
                        "neighbouring tile does too) and subdivides its pixels, so no corner crosses the links")
          : fmt::format("each cell traces the corners it owns, exchanges corners with its neighbours over the {} "
                        "links (a vertical step, then a horizontal one that relays) and subdivides its pixels",
                        to_string(r.config.profile.link.topology)),
      grouped(t.messages),
      grouped(t.bytes), grouped(t.hops), t.max_hops, grouped(t.busiest.count()), t.busiest.seconds(hz),
      grouped(t.longest_wait.count()), r.links.size(), link_heads, links);
}

// Balanced on demand: how the tiles were handed out, the bus traffic that
// cost, and the map of which cell traced each tile (drawn by the script from
// the report's balancing.tile_cells).
std::string balancing_section(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const Host::Balancing& h = r.balancing;
  return fmt::format(
      "<section id=\"balancing\">\n<h2>Balancing on demand</h2>\n<p>The host hands out tiles of at most {0}x{0} "
      "pixels, in order, to the cells that ask over the command bus; each cell asks for its next tile as the one "
      "it traces nears its end (docs/balancing.md). The table of cells gives each cell's tiles, requests and "
      "waits.</p>\n<table id=\"balance-totals\" class=\"facts\">\n<caption>Balancing traffic</caption>\n"
      "<tr><th>Requests</th><td>{1} ({2} B)</td></tr>\n<tr><th>Grants</th><td>{3}</td></tr>\n"
      "<tr><th>&ldquo;No tile&rdquo; answers</th><td>{4}</td></tr>\n"
      "<tr><th>Bus held for balancing</th><td>{5} transfers, {6} B, {7} cycles ({8:.4f} s), {9:.3f} % of the "
      "run</td></tr>\n</table>\n<p class=\"note\">Which cell traced each tile, one colour a cell; hover for the "
      "tile and its cell.</p>\n<div id=\"tile-map\" class=\"tile-map\"></div>\n</section>\n",
      r.config.balance.tile_side(), grouped(h.requests), grouped(h.bytes_received), grouped(h.grants),
      grouped(h.refusals), grouped(r.balance_bus.transfers), grouped(r.balance_bus.bytes),
      grouped(r.balance_bus.busy.count()), r.balance_bus.busy.seconds(hz), balance_bus_percent(r));
}

// Stealing: what the cells took from each other over the links, and the map
// of which cell traced each pixel (drawn by the script from the page's
// completion data, whose chunks name their tracers).
std::string stealing_section(const SimulationResult& r) {
  std::uint64_t requests = 0, refused = 0, stolen = 0, chunks = 0;
  for (const CellReport& c : r.cells) {
    requests += c.steal_requests;
    refused += c.steals_refused;
    stolen += c.chunks_stolen;
  }
  for (const auto& frame : r.chunk_cells)
    for (const auto& window : frame) chunks += window.size();
  return fmt::format(
      "<section id=\"stealing\">\n<h2>Stealing</h2>\n<p>Each cell traces the chunks of {0} pixels its window "
      "shows ({1} mode), front to back; a cell that has traced its own asks its neighbours over the links for "
      "half of their unstarted chunks and sends back the pixels it traces of them (docs/balancing.md). The "
      "table of cells gives each cell's chunks, requests and waits.</p>\n<table id=\"steal-totals\" "
      "class=\"facts\">\n<caption>Stealing traffic</caption>\n"
      "<tr><th>Chunks</th><td>{2}, {3} of them stolen</td></tr>\n"
      "<tr><th>Requests</th><td>{4}, {5} answered &ldquo;no work&rdquo;</td></tr>\n"
      "<tr><th>Link messages for stealing</th><td>{6} ({7} B)</td></tr>\n</table>\n<p class=\"note\">Which "
      "cell traced each pixel, one colour a cell; hover for the pixel and its cell.</p>\n"
      "<div id=\"chunk-map\" class=\"tile-map\"></div>\n</section>\n",
      r.config.balance.chunk_pixels, to_string(r.config.mode), grouped(chunks), grouped(stolen), grouped(requests),
      grouped(refused), grouped(r.steal_links.messages), grouped(r.steal_links.bytes));
}

std::string sequence_section(const SimulationResult& r) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  std::string frames;
  const std::vector<LoadSpread> fs = frame_spreads(r);
  for (std::size_t f = 0; f < fs.size(); ++f)
    frames += fmt::format("<tr><td>{}</td>{}{}<td>{:.2f}</td></tr>\n", f, seconds_cell(fs[f].max_finish, hz),
                          seconds_cell(fs[f].min_finish, hz), fs[f].deviation_percent);
  std::string units;
  if (r.config.frame_average) {
    const std::vector<LoadSpread> us = unit_spreads(r);
    for (std::size_t u = 0; u < us.size(); ++u)
      units += fmt::format("<tr><td>{}</td><td>{}</td>{}{}<td>{:.2f}</td><td>{}</td></tr>\n", u, r.units[u].frames,
                           seconds_cell(us[u].max_finish, hz), seconds_cell(us[u].min_finish, hz),
                           us[u].deviation_percent, grouped(r.units[u].video_memory_bytes));
    units = "<div class=\"table-box\"><table id=\"unit-table\" class=\"numbers\">\n<caption>Per group of frames: "
            "the cells' &ldquo;done&rdquo; from the group's start, and the most video memory a cell "
            "needs</caption>\n<thead><tr><th>Group</th><th>Frames</th><th>Max s</th><th>Min s</th><th>d %</th>"
            "<th>Video memory B</th></tr></thead>\n<tbody>\n" +
            units + "</tbody>\n</table></div>\n";
  }
  const nlohmann::json report = report_json(r);
  return fmt::format(
      "<section id=\"sequence\">\n<h2>Frames</h2>\n<p>{}</p>\n<div id=\"frame-chart\" class=\"chart\"></div>\n"
      "<div class=\"table-box\"><table id=\"frame-table\" class=\"numbers\">\n<caption>Per frame: Max, Min and "
      "d</caption>\n<thead><tr><th>Frame</th><th>Max s</th><th>Min s</th><th>d %</th></tr></thead>\n<tbody>\n{}"
      "</tbody>\n</table></div>\n{}<table id=\"table-4-5\" class=\"numbers\">\n<caption>Table 4-5's form, {} "
      "frames</caption>\n<thead><tr><th>Processing</th><th>Time</th><th>Max deviation</th></tr></thead>\n"
      "<tbody><tr><td>{}</td><td title=\"{} cycles\">{:.3f} s</td><td>{:.2f} %</td></tr></tbody>\n</table>\n"
      "</section>\n",
      r.config.frame_average
          ? "Frame averaged: each frame's Max, Min and d are of the cycles every cell worked on it."
          : "Each frame from its start to the cells' &ldquo;done&rdquo; reaching the host.",
      frames, units, r.screens.size(), report["sequence"]["processing"].get<std::string>(), grouped(r.frame.count()),
      r.frame.seconds(hz), max_deviation_percent(r));
}

// The data the page's script reads beside the report and the trace: each
// frame's windows ([origin_x, origin_y, columns, rows, stride_x, stride_y] per
// cell in id order; on demand, per tile in tile order, with window_cells
// naming the cell that traced each) and its packed completion cycles in
// base64.
std::string page_data(const SimulationResult& r) {
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t f = 0; f < r.screens.size(); ++f) {
    const WindowLayout layout = frame_layout(r.config, r.width, r.height, static_cast<int>(f));
    nlohmann::json windows = nlohmann::json::array();
    for (CellId c = 0; c < layout.grid().cell_count(); ++c) {
      const CellWindow& w = layout.window(c);
      windows.push_back({w.origin_x(), w.origin_y(), w.columns(), w.rows(), w.stride_x(), w.stride_y()});
    }
    const bool stealing = r.config.balance.stealing();
    const std::vector<unsigned char> packed =
        pack_completion_cycles(r.screens[f].completion_cycles, layout, stealing);
    const std::size_t unit = static_cast<std::size_t>(
        std::find_if(r.units.begin(), r.units.end(),
                     [&](const UnitTimes& u) {
                       return static_cast<int>(f) >= u.first_frame && static_cast<int>(f) < u.first_frame + u.frames;
                     }) -
        r.units.begin());
    frames.push_back({{"windows", windows},
                      {"start_cycles", r.units.at(unit).start.count()},
                      {"completion", base64(packed)}});
    if (r.config.balance.on_demand()) frames.back()["window_cells"] = r.tile_cells.at(f);
    if (stealing) {
      frames.back()["signed"] = true;
      frames.back()["chunk_pixels"] = r.config.balance.chunk_pixels;
      frames.back()["chunk_cells"] = r.chunk_cells.at(f);
    }
  }
  return nlohmann::json{{"frames", frames}}.dump();
}

std::string data_block(const char* id, std::string_view json) {
  return fmt::format("<script type=\"application/json\" id=\"{}\">{}</script>\n", id, script_safe_json(json));
}

}  // namespace

std::string run_name(const std::vector<std::string>& scenes, std::size_t frames) {
  const auto name = [](const std::string& path) { return std::filesystem::path(path).filename().string(); };
  if (scenes.empty()) return "";
  if (frames <= 1) return name(scenes.front());
  if (scenes.size() == 1) return fmt::format("{} ({} frames)", name(scenes.front()), frames);
  return fmt::format("{} {} {} ({} frames)", name(scenes.front()), scenes.size() == 2 ? "and" : "...",
                     name(scenes.back()), frames);
}

std::string html_report(const SimulationResult& r, const RunFacts& facts) {
  for (const FrameScreen& s : r.screens)
    if (s.completion_cycles.size() != static_cast<std::size_t>(r.width) * r.height)
      throw std::logic_error("the HTML report needs the completion cycles (MachineConfig::completion_cycles)");
  std::string body = header_section(r, facts) + "<main>\n" + run_section(r, facts) + screen_section(r) +
                     cells_section(r) + timeline_section() + breakdown_section(r);
  if (r.config.aa.depth > 0) body += antialiasing_section(r);
  if (r.config.balance.on_demand()) body += balancing_section(r);
  if (r.config.balance.stealing()) body += stealing_section(r);
  if (r.screens.size() > 1) body += sequence_section(r);
  body += fmt::format(
      "</main>\n<footer>Written by capsim {}. The --report JSON and the --trace JSON of this run are in this file, "
      "in the elements with ids report-data and trace-data.</footer>\n",
      html_escape(facts.version));
  body += data_block("report-data", report_json_text(r, provenance_of(facts)));
  body += data_block("trace-data", chrome_trace_text(r));
  body += data_block("page-data", page_data(r));

  const std::string sharing = r.config.balance.on_demand() ? "balanced " + to_string(r.config.balance)
                              : r.config.balance.stealing()
                                  ? fmt::format("{} mode, {}", to_string(r.config.mode), to_string(r.config.balance))
                                  : fmt::format("{} mode", to_string(r.config.mode));
  const std::string title = fmt::format("capsim: {}, {} cells, {}", run_name(facts.scenes, r.screens.size()),
                                        to_string(r.config.cells), sharing);
  const HtmlAssets& assets = html_assets();
  const std::string escaped_title = html_escape(title);
  return fill_template(assets.page,
              {{"@TITLE@", escaped_title}, {"@STYLE@", assets.style}, {"@BODY@", body}, {"@SCRIPT@", assets.script}});
}

}  // namespace capsim::sim
