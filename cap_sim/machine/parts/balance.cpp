#include "machine/parts/balance.h"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace capsim::sim {

namespace {

// The whole square root of n, or 0 if n is not a square.
int exact_square_root(int n) {
  int s = 0;
  while ((s + 1) * (s + 1) <= n) ++s;
  return s * s == n ? s : 0;
}

}  // namespace

int BalanceOptions::tile_side() const { return exact_square_root(tile_pixels); }

namespace {

// "steal" or "steal:CHUNK", CHUNK a whole number from 1 to kMaxChunkPixels.
BalanceOptions parse_steal(const std::string& text) {
  BalanceOptions b;
  b.scheme = BalanceScheme::Steal;
  if (text == "steal") return b;
  const std::string chunk = text.substr(std::string("steal:").size());
  int pixels = 0;
  const auto [end, ec] = std::from_chars(chunk.data(), chunk.data() + chunk.size(), pixels);
  if (ec != std::errc() || end != chunk.data() + chunk.size() || pixels < 1 || pixels > kMaxChunkPixels)
    throw std::invalid_argument(
        fmt::format("steal's chunk \"{}\" is not a whole number of pixels from 1 to {} (e.g. 16)", chunk,
                    kMaxChunkPixels));
  b.chunk_pixels = pixels;
  return b;
}

}  // namespace

BalanceOptions parse_balance(const std::string& text) {
  if (text == "static") return {};
  if (text == "steal" || text.rfind("steal:", 0) == 0) return parse_steal(text);
  const std::string demand = "demand";
  if (text == demand) return {BalanceScheme::Demand, kDefaultTilePixels};
  const std::string prefix = demand + ":";
  if (text.rfind(prefix, 0) == 0) {
    const std::string tile = text.substr(prefix.size());
    int pixels = 0;
    const auto [end, ec] = std::from_chars(tile.data(), tile.data() + tile.size(), pixels);
    if (ec == std::errc() && end == tile.data() + tile.size() && pixels >= 1 && pixels <= kMaxTilePixels &&
        exact_square_root(pixels) > 0)
      return {BalanceScheme::Demand, pixels, kDefaultChunkPixels};
    throw std::invalid_argument(fmt::format(
        "demand's tile \"{}\" is not a square number of pixels from 1 to {} (e.g. 16, 64, 256)", tile,
        kMaxTilePixels));
  }
  throw std::invalid_argument(
      fmt::format("\"{}\" is not a balance scheme: static, demand, demand:TILE (TILE a square number of "
                  "pixels, e.g. demand:64), steal or steal:CHUNK (e.g. steal:16)",
                  text));
}

std::string to_string(const BalanceOptions& balance) {
  if (balance.on_demand()) return fmt::format("demand:{}", balance.tile_pixels);
  if (balance.stealing()) return fmt::format("steal:{}", balance.chunk_pixels);
  return "static";
}

int chunk_count(int pixels, int chunk_pixels) { return (pixels + chunk_pixels - 1) / chunk_pixels; }

ChunkRange chunk_range(int k, int pixels, int chunk_pixels) {
  const int first = k * chunk_pixels;
  return {first, std::min(pixels, first + chunk_pixels) - first};
}

WindowLayout tile_layout(const BalanceOptions& balance, int width, int height) {
  const int side = balance.tile_side();
  if (!balance.on_demand() || side < 1) throw std::logic_error("tiles need --balance demand with a square tile");
  return WindowLayout(PixelMode::Block, CellGrid{(height + side - 1) / side, (width + side - 1) / side}, width,
                      height);
}

}  // namespace capsim::sim
