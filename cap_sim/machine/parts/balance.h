#pragma once
// How the work of a frame is shared among the cells (docs/balancing.md):
//   static: the paper's (§3.2): every cell traces the pixels its window
//           controller shows (block, line or dot mode), fixed before the frame;
//   demand: LINKS-1's scheme on the CAP: the host hands out square tiles of
//           the screen to the cells that ask for one, over the command bus;
//   steal:  the static distribution, its windows cut into chunks of CHUNK
//           pixels in video-memory order; a cell that has traced its own
//           asks its neighbours over the links for half of their unstarted
//           chunks, and sends the pixels it traces of them back to the
//           owner's video memory (docs/balancing.md).
// Demand's tiles are the blocks of a block-mode layout whose "cells" are the
// tiles: for a tile of TILE = s x s pixels, the screen is cut into ceil(H / s)
// rows and ceil(W / s) columns of tiles, as evenly as block mode cuts it, so
// every tile is at most s x s and tiles differ by at most one pixel a side.
// Tile t is the block of that layout's cell t: tiles are numbered row by row
// from the top left, the order the host hands them out in.

#include "machine/parts/window_controller.h"

#include <cstdint>
#include <string>

namespace capsim::sim {

enum class BalanceScheme { Static, Demand, Steal };

inline constexpr int kDefaultTilePixels = 64;
// The largest tile --balance demand:TILE accepts: 256 x 256 pixels.
inline constexpr int kMaxTilePixels = 65536;
inline constexpr int kDefaultChunkPixels = 16;
// The largest chunk --balance steal:CHUNK accepts.
inline constexpr int kMaxChunkPixels = 65536;

struct BalanceOptions {
  BalanceScheme scheme = BalanceScheme::Static;
  // Demand: pixels of a tile, a square number (the paper's 8 x 8 square by
  // default).
  int tile_pixels = kDefaultTilePixels;
  // Steal: pixels of a chunk, the unit a cell gives away.
  int chunk_pixels = kDefaultChunkPixels;

  bool is_static() const { return scheme == BalanceScheme::Static; }
  bool on_demand() const { return scheme == BalanceScheme::Demand; }
  bool stealing() const { return scheme == BalanceScheme::Steal; }
  int tile_side() const;
  bool operator==(const BalanceOptions&) const = default;
};

// "static", "demand" (the default tile), "demand:TILE", "steal" (the default
// chunk) or "steal:CHUNK"; throws std::invalid_argument saying what is
// accepted otherwise.
BalanceOptions parse_balance(const std::string& text);
// "static", "demand:TILE" or "steal:CHUNK", as parse_balance takes it back.
std::string to_string(const BalanceOptions& balance);

// Stealing: the chunks of a window of `pixels` pixels: chunk k holds its
// pixels k * CHUNK to min(pixels, (k + 1) * CHUNK) - 1 in video-memory order.
struct ChunkRange {
  int first_pixel = 0, pixels = 0;
};
int chunk_count(int pixels, int chunk_pixels);
ChunkRange chunk_range(int k, int pixels, int chunk_pixels);

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

// Stealing's messages over the neighbour links, their sizes in bytes:
//   thief -> victim  steal request  the thief's id
//   victim -> thief  work           frame (16 bits), first chunk (32 bits) and
//                                   chunks (16 bits); antialiased, followed by
//                                   the 4 corner samples of every pixel
//   victim -> thief  no work        nothing unstarted to give
//   thief -> owner   pixels         the grant's header again and its pixels,
//                                   kVideoPixelBytes each, for the owner's
//                                   video memory
inline constexpr std::uint64_t kStealRequestBytes = 4;
inline constexpr std::uint64_t kStolenWorkHeaderBytes = 8;
inline constexpr std::uint64_t kNoWorkBytes = 4;
}  // namespace capsim::sim
