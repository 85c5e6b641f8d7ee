// The PNG's image data compressed in bands: one zlib stream that inflates to
// its input whatever the band size, the same bytes on any number of threads,
// and the end of a band's block placed where zlib's own decoder finds it.

#include "image/zlib_bands.h"

#include <gtest/gtest.h>
#include <libdeflate.h>
#include <zlib.h>

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace capsim;

namespace {

using Bytes = std::vector<unsigned char>;

Bytes inflate_zlib(std::span<const unsigned char> stream, std::size_t expected) {
  Bytes out(expected + 1);
  uLongf size = out.size();
  const int rc = uncompress(out.data(), &size, stream.data(), stream.size());
  EXPECT_EQ(rc, Z_OK);
  out.resize(rc == Z_OK ? size : 0);
  return out;
}

// Pseudo-random bytes of kinds that reach each way a band is written.
Bytes noise(std::size_t n, std::uint32_t seed) {
  Bytes b(n);
  for (unsigned char& c : b) {
    seed = seed * 1664525u + 1013904223u;
    c = static_cast<unsigned char>(seed >> 24);
  }
  return b;
}

// Rows of a smooth picture with a little noise, Sub-filtered: what a render
// gives libdeflate (mostly one dynamic block per band).
Bytes picture(std::size_t n) {
  Bytes b(n);
  std::uint32_t seed = 99;
  for (std::size_t k = 0; k < n; ++k) {
    seed = seed * 1664525u + 1013904223u;
    b[k] = static_cast<unsigned char>((k / 3000) % 7 + ((seed >> 29) == 0 ? seed >> 24 : 0));
  }
  return b;
}

// Words drawn from four: matches of 4 bytes or so all the way, more than
// 8,192 to a band, so libdeflate writes several blocks and zlib takes the band.
Bytes short_matches(std::size_t n) {
  const unsigned char words[4][4] = {{1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}, {13, 14, 15, 16}};
  Bytes b(n);
  std::uint32_t seed = 7;
  for (std::size_t k = 0; k < n; k += 4) {
    seed = seed * 1664525u + 1013904223u;
    for (std::size_t i = 0; i < 4 && k + i < n; ++i) b[k + i] = words[seed >> 30][i];
  }
  return b;
}

Bytes libdeflate_raw(std::span<const unsigned char> in) {
  libdeflate_compressor* c = libdeflate_alloc_compressor(1);
  Bytes out(libdeflate_deflate_compress_bound(c, in.size()));
  out.resize(libdeflate_deflate_compress(c, in.data(), in.size(), out.data(), out.size()));
  libdeflate_free_compressor(c);
  return out;
}

// Where zlib's decoder finishes a raw DEFLATE stream's last block: bits
// consumed, from the bytes it took less the bits it left unused in the last
// one. Z_BLOCK stops it there before it drops the padding.
std::size_t zlib_end_bits(std::span<const unsigned char> deflate, std::size_t expected) {
  z_stream z{};
  EXPECT_EQ(inflateInit2(&z, -15), Z_OK);
  Bytes out(expected + 1);
  z.next_in = const_cast<unsigned char*>(deflate.data());
  z.avail_in = static_cast<uInt>(deflate.size());
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  constexpr int kAfterLastBlock = 64 + 128;  // in the last block, just after its end code
  while ((z.data_type & kAfterLastBlock) != kAfterLastBlock) {
    const int rc = inflate(&z, Z_BLOCK);
    if (rc != Z_OK && rc != Z_STREAM_END) {
      ADD_FAILURE() << "inflate: " << rc;
      break;
    }
  }
  const std::size_t end = z.total_in * 8 - static_cast<std::size_t>(z.data_type & 7);
  EXPECT_EQ(z.total_out, expected);
  inflateEnd(&z);
  return end;
}

// A final dynamic-Huffman block that holds only its end: literal/length
// codes of one bit for symbols 256 (end of block, code 0) and 257, one
// distance code. The header's code lengths are two runs of zeros (code 18)
// and three 1s (code 1), in a code-length code of one bit each.
Bytes end_code_of_one_zero_bit() {
  Bytes out;
  std::size_t bits = 0;
  const auto put = [&](unsigned value, int n) {
    for (int i = 0; i < n; ++i, ++bits) {
      if (bits % 8 == 0) out.push_back(0);
      out.back() |= static_cast<unsigned char>(((value >> i) & 1) << (bits % 8));
    }
  };
  put(1, 1);   // final
  put(2, 2);   // dynamic
  put(1, 5);   // 258 literal/length codes
  put(0, 5);   // 1 distance code
  put(14, 4);  // 18 code-length code lengths, in RFC 1951's order
  for (int i = 0; i < 18; ++i) put(i == 2 || i == 17 ? 1 : 0, 3);  // symbols 18 and 1: one bit each
  put(1, 1);   // 18: zeros ...
  put(127, 7);  // ... 138 of them
  put(1, 1);
  put(107, 7);  // 118 more: 256 in all
  for (int i = 0; i < 3; ++i) put(0, 1);  // 1: lengths of 256, 257 and the distance code
  put(0, 1);   // end of block
  return out;
}

TEST(ZlibBands, InflateToTheirInputAtEveryBandSize) {
  const std::vector<std::pair<std::string, Bytes>> inputs = {
      {"empty", {}},
      {"one byte", Bytes{42}},
      {"noise", noise(200'000, 5)},
      {"zeros", Bytes(150'001, 0)},
      {"picture", picture(300'000)},
      {"short matches", short_matches(120'000)},
  };
  for (const auto& [name, input] : inputs) {
    for (const std::size_t band : {std::size_t{1}, std::size_t{7}, std::size_t{1000}, std::size_t{65'536},
                                   kZlibBandBytes}) {
      if (band < 1000 && input.size() > 20'000) continue;  // a band per byte: slow, nothing new
      const ZlibStream s = zlib_compress_in_bands(input, 2, band);
      const Bytes joined = s.joined();
      ASSERT_EQ(joined.size(), s.size());
      EXPECT_EQ(joined[0], 0x78);
      EXPECT_EQ(joined[1], 0x01);
      EXPECT_TRUE(inflate_zlib(joined, input.size()) == input) << name << ", bands of " << band;
      EXPECT_LE(s.size(), zlib_compress_in_bands_memory(input.size(), band)) << name << ", bands of " << band;
    }
  }
}

TEST(ZlibBands, GiveTheSameBytesOnAnyNumberOfThreads) {
  Bytes input = picture(500'000);
  const Bytes more = short_matches(100'000);
  input.insert(input.end(), more.begin(), more.end());
  const ZlibStream one = zlib_compress_in_bands(input, 1);
  ASSERT_TRUE(inflate_zlib(one.joined(), input.size()) == input);
  for (const int threads : {2, 3, 8, 0}) {
    const ZlibStream many = zlib_compress_in_bands(input, threads);
    EXPECT_TRUE(many.joined() == one.joined())
        << threads << " threads";
  }
}

// Every band shape the bands meet: the end single_block_end gives is the end
// zlib's decoder reaches, and it gives one for the dynamic blocks that
// rendered images make.
TEST(ZlibBands, PlaceABlocksEndWhereZlibFindsIt) {
  int placed = 0, dynamic = 0;
  for (std::size_t n = 1; n < 60'000; n = n * 3 / 2 + 1) {
    for (const Bytes& input : {picture(n), noise(n, static_cast<std::uint32_t>(n)), Bytes(n, 3)}) {
      const Bytes raw = libdeflate_raw(input);
      const std::optional<std::size_t> end = single_block_end(raw);
      const bool one_dynamic_block = (raw[0] & 7) == 5;  // final, type 2
      dynamic += one_dynamic_block;
      if (!end) continue;
      ++placed;
      EXPECT_EQ(*end, zlib_end_bits(raw, input.size())) << n << " bytes";
      EXPECT_GE(*end + 8, raw.size() * 8);
    }
  }
  EXPECT_GT(dynamic, 20);
  EXPECT_GE(placed, dynamic);  // stored blocks are placed too
}

TEST(ZlibBands, LeaveUnplacedWhatTheyCannotPlace) {
  // Several blocks: the first is not final.
  const Bytes several = libdeflate_raw(short_matches(65'000));
  ASSERT_EQ(several[0] & 1, 0);
  EXPECT_FALSE(single_block_end(several));
  // A fixed-Huffman block: its end-of-block code is seven zero bits, which fit
  // the padding at several places.
  const Bytes fixed = libdeflate_raw(Bytes(300, 0));
  ASSERT_EQ(fixed[0] & 7, 3);
  EXPECT_FALSE(single_block_end(fixed));
  // A dynamic block whose end-of-block code is the single bit 0: it, and so
  // the block's end, reads the same at every place in the padding.
  const Bytes zero_end = end_code_of_one_zero_bit();
  ASSERT_EQ(zlib_end_bits(zero_end, 0), 91u);  // the bits it was written with
  EXPECT_FALSE(single_block_end(zero_end));
  // A stored block ends with the stream.
  const Bytes stored = libdeflate_raw(noise(40, 1));
  ASSERT_EQ(stored[0] & 7, 1);
  EXPECT_EQ(single_block_end(stored), stored.size() * 8);
  // Malformed or cut short.
  EXPECT_FALSE(single_block_end(Bytes{}));
  EXPECT_FALSE(single_block_end(Bytes{0x07}));
  Bytes cut = libdeflate_raw(picture(20'000));
  ASSERT_EQ(cut[0] & 7, 5);
  cut.resize(6);
  EXPECT_FALSE(single_block_end(cut));
}

// Whatever the bytes, the reader stays inside them (the sanitizer build
// checks): a dynamic block cut at every length, and noise.
TEST(ZlibBands, ReadNothingPastTheirInput) {
  const Bytes whole = libdeflate_raw(picture(5'000));
  ASSERT_EQ(whole[0] & 7, 5);
  ASSERT_TRUE(single_block_end(whole));
  for (std::size_t n = 0; n < whole.size(); ++n) {
    const Bytes cut(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(n));
    const std::optional<std::size_t> end = single_block_end(cut);
    if (end) {
      EXPECT_LE(*end, n * 8);
    }
  }
  for (std::uint32_t seed = 0; seed < 2'000; ++seed) {
    Bytes b = noise(1 + seed % 300, seed);
    b[0] = static_cast<unsigned char>((b[0] & ~7u) | 5u);  // final, dynamic
    const std::optional<std::size_t> end = single_block_end(b);
    if (end) {
      EXPECT_LE(*end, b.size() * 8);
    }
  }
}

}  // namespace

// Bands compressed one at a time, in any order and on any thread, make the
// stream compressing the whole input at once makes; a band left out, or given
// the wrong input size, is refused.
TEST(ZlibBands, WrittenBandByBandGiveTheWholeInputsStream) {
  const Bytes input = picture(300'000);
  const ZlibStream whole = zlib_compress_in_bands(input, 1);
  ZlibBandWriter writer(input.size());
  ASSERT_EQ(writer.bands(), 7u);  // 6 whole bands of 48 KiB and a last of 5,088 bytes
  EXPECT_EQ(writer.band_size(6), 300'000 - 6 * kZlibBandBytes);
  const auto band = [&](std::size_t b) {
    return std::span<const unsigned char>(input).subspan(b * kZlibBandBytes, writer.band_size(b));
  };
  EXPECT_THROW(writer.compress(0, band(6)), std::logic_error);
  EXPECT_THROW(writer.compress(7, {}), std::logic_error);
  std::thread other([&] {
    for (const std::size_t b : {5u, 1u, 3u}) writer.compress(b, band(b));
  });
  for (const std::size_t b : {6u, 0u, 4u, 2u}) writer.compress(b, band(b));
  other.join();
  const ZlibStream banded = writer.finish();
  EXPECT_TRUE(banded.joined() == whole.joined());

  ZlibBandWriter missing(input.size());
  for (std::size_t b = 0; b + 1 < missing.bands(); ++b) missing.compress(b, band(b));
  EXPECT_THROW(missing.finish(), std::logic_error);
}
