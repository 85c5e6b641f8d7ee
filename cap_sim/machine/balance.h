#pragma once
// How the work of a frame is shared among the cells (docs/balancing.md):
//   static: the paper's (§3.2): every cell traces the pixels its window
//           controller shows (block, line or dot mode), fixed before the frame;
//   demand: LINKS-1's scheme on the CAP: the host hands out square tiles of
//           the screen to the cells that ask for one, over the command bus.
// Demand's tiles are the blocks of a block-mode layout whose "cells" are the
// tiles: for a tile of TILE = s x s pixels, the screen is cut into ceil(H / s)
// rows and ceil(W / s) columns of tiles, as evenly as block mode cuts it, so
// every tile is at most s x s and tiles differ by at most one pixel a side.
// Tile t is the block of that layout's cell t: tiles are numbered row by row
// from the top left, the order the host hands them out in.

#include "machine/window_controller.h"

#include <cstdint>
#include <string>

namespace capsim::sim {

enum class BalanceScheme { Static, Demand };

struct BalanceOptions {
  BalanceScheme scheme = BalanceScheme::Static;
  // Demand: pixels of a tile, a square number (the paper's 8 x 8 square by
  // default).
  int tile_pixels = 64;

  bool on_demand() const { return scheme == BalanceScheme::Demand; }
  int tile_side() const;
  bool operator==(const BalanceOptions&) const = default;
};

inline constexpr int kDefaultTilePixels = 64;
// The largest tile --balance demand:TILE accepts: 256 x 256 pixels.
inline constexpr int kMaxTilePixels = 65536;

// "static", "demand" (the default tile) or "demand:TILE"; throws
// std::invalid_argument saying what is accepted otherwise.
BalanceOptions parse_balance(const std::string& text);
// "static" or "demand:TILE", as parse_balance takes it back.
std::string to_string(const BalanceOptions& balance);

// The tiles of a width x height screen (see above). Precondition: demand.
WindowLayout tile_layout(const BalanceOptions& balance, int width, int height);

// The balancing messages on the command bus, their sizes in bytes:
//   cell -> host  request   the asking cell's id
//   host -> cell  grant     the tile's screen rectangle: x, y, width, height,
//                           16 bits each, which the cell's window controller
//                           takes as the tile's place on the screen
//   host -> cell  no tile   every tile of the unit is handed out
inline constexpr std::uint64_t kTileRequestBytes = 4;
inline constexpr std::uint64_t kTileGrantBytes = 8;
inline constexpr std::uint64_t kNoTileBytes = 4;

}  // namespace capsim::sim
