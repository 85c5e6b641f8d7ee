#include "machine/balance.h"

#include <fmt/core.h>

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

BalanceOptions parse_balance(const std::string& text) {
  if (text == "static") return {};
  const std::string demand = "demand";
  if (text == demand) return {BalanceScheme::Demand, kDefaultTilePixels};
  const std::string prefix = demand + ":";
  if (text.rfind(prefix, 0) == 0) {
    const std::string tile = text.substr(prefix.size());
    int pixels = 0;
    const auto [end, ec] = std::from_chars(tile.data(), tile.data() + tile.size(), pixels);
    if (ec == std::errc() && end == tile.data() + tile.size() && pixels >= 1 && pixels <= kMaxTilePixels &&
        exact_square_root(pixels) > 0)
      return {BalanceScheme::Demand, pixels};
    throw std::invalid_argument(fmt::format(
        "demand's tile \"{}\" is not a square number of pixels from 1 to {} (e.g. 16, 64, 256)", tile,
        kMaxTilePixels));
  }
  throw std::invalid_argument(
      fmt::format("\"{}\" is not a balance scheme: static, demand or demand:TILE (TILE a square number of "
                  "pixels, e.g. demand:64)",
                  text));
}

std::string to_string(const BalanceOptions& balance) {
  return balance.on_demand() ? fmt::format("demand:{}", balance.tile_pixels) : "static";
}

WindowLayout tile_layout(const BalanceOptions& balance, int width, int height) {
  const int side = balance.tile_side();
  if (!balance.on_demand() || side < 1) throw std::logic_error("tiles need --balance demand with a square tile");
  return WindowLayout(PixelMode::Block, CellGrid{(height + side - 1) / side, (width + side - 1) / side}, width,
                      height);
}

}  // namespace capsim::sim
