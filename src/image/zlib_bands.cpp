#include "image/zlib_bands.h"

#include "capsim/system/host_threads.h"

#include <libdeflate.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <mutex>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

namespace capsim {

namespace {

// Reads a DEFLATE stream's bits, least significant first (RFC 1951, 3.1.1).
class BitReader {
 public:
  explicit BitReader(std::span<const unsigned char> data) : data_(data) {}

  bool bit(std::size_t at) const { return (data_[at >> 3] >> (at & 7)) & 1; }
  std::size_t position() const { return position_; }
  std::size_t size_bits() const { return data_.size() * 8; }

  // The next n (<= 16) bits as a number, or -1 past the end.
  int take(int n) {
    if (position_ + static_cast<std::size_t>(n) > size_bits()) return -1;
    int value = 0;
    for (int i = 0; i < n; ++i) value |= static_cast<int>(bit(position_ + i)) << i;
    position_ += static_cast<std::size_t>(n);
    return value;
  }

 private:
  std::span<const unsigned char> data_;
  std::size_t position_ = 0;
};

// A canonical Huffman code (RFC 1951, 3.2.2) given by its code lengths.
struct CanonicalCode {
  static constexpr int kMaxBits = 15;
  std::array<int, kMaxBits + 1> count{};  // codes of each length
  std::vector<int> symbols;               // by length, then by symbol

  // False if the lengths over-subscribe the code (no prefix code has them).
  bool build(std::span<const int> lengths) {
    count.fill(0);
    for (int l : lengths) ++count[static_cast<std::size_t>(l)];
    count[0] = 0;
    int left = 1;
    for (int len = 1; len <= kMaxBits; ++len) {
      left = 2 * left - count[static_cast<std::size_t>(len)];
      if (left < 0) return false;
    }
    std::array<int, kMaxBits + 2> offset{};
    for (int len = 1; len <= kMaxBits; ++len) offset[len + 1] = offset[len] + count[len];
    symbols.assign(static_cast<std::size_t>(offset[kMaxBits + 1]), 0);
    for (std::size_t s = 0; s < lengths.size(); ++s)
      if (lengths[s] != 0) symbols[static_cast<std::size_t>(offset[lengths[s]]++)] = static_cast<int>(s);
    return true;
  }

  // The next symbol, its code read first bit first; -1 if none.
  int decode(BitReader& in) const {
    int code = 0, first = 0, index = 0;
    for (int len = 1; len <= kMaxBits; ++len) {
      const int bit = in.take(1);
      if (bit < 0) return -1;
      code |= bit;
      const int n = count[static_cast<std::size_t>(len)];
      if (code - first < n) return symbols[static_cast<std::size_t>(index + code - first)];
      index += n;
      first = (first + n) << 1;
      code <<= 1;
    }
    return -1;
  }

  // The code of `symbol` in the code build() made from `lengths`; its length
  // is lengths[symbol] (> 0). RFC 1951's next_code, then the symbols before
  // it of the same length.
  int code_of(std::span<const int> lengths, int symbol) const {
    const int length = lengths[static_cast<std::size_t>(symbol)];
    int code = 0;
    for (int len = 1; len < length; ++len) code = (code + count[static_cast<std::size_t>(len)]) << 1;
    for (int s = 0; s < symbol; ++s) code += lengths[static_cast<std::size_t>(s)] == length;
    return code;
  }
};

// The literal/length code lengths of a dynamic block's header (RFC 1951,
// 3.2.7), `in` just past the block type; empty if malformed.
std::optional<std::vector<int>> dynamic_literal_lengths(BitReader& in) {
  const int hlit = in.take(5), hdist = in.take(5), hclen = in.take(4);
  if (hlit < 0 || hdist < 0 || hclen < 0 || hlit + 257 > 286 || hdist + 1 > 30) return std::nullopt;
  constexpr std::array<int, 19> kOrder = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
  std::array<int, 19> length_lengths{};
  for (int i = 0; i < hclen + 4; ++i) {
    const int l = in.take(3);
    if (l < 0) return std::nullopt;
    length_lengths[static_cast<std::size_t>(kOrder[static_cast<std::size_t>(i)])] = l;
  }
  CanonicalCode length_code;
  if (!length_code.build(length_lengths)) return std::nullopt;
  const int total = hlit + 257 + hdist + 1;
  std::vector<int> lengths;
  lengths.reserve(static_cast<std::size_t>(total));
  while (static_cast<int>(lengths.size()) < total) {
    const int symbol = length_code.decode(in);
    if (symbol < 0) return std::nullopt;
    if (symbol < 16) {
      lengths.push_back(symbol);
      continue;
    }
    // 16: the last length again, 3-6 times; 17: zeros, 3-10; 18: zeros, 11-138.
    if (symbol == 16 && lengths.empty()) return std::nullopt;
    const int value = symbol == 16 ? lengths.back() : 0;
    const int extra = in.take(symbol == 16 ? 2 : symbol == 17 ? 3 : 7);
    const int repeat = (symbol == 18 ? 11 : 3) + extra;
    if (extra < 0 || static_cast<int>(lengths.size()) + repeat > total) return std::nullopt;
    lengths.insert(lengths.end(), static_cast<std::size_t>(repeat), value);
  }
  lengths.resize(static_cast<std::size_t>(hlit + 257));
  return lengths;
}

}  // namespace

std::optional<std::size_t> single_block_end(std::span<const unsigned char> deflate) {
  BitReader in(deflate);
  const int final_bit = in.take(1), type = in.take(2);
  if (final_bit != 1) return std::nullopt;
  if (type == 0) {
    // Stored: LEN and NLEN from the next byte, then LEN bytes to the end.
    if (deflate.size() < 5) return std::nullopt;
    const unsigned len = deflate[1] | (deflate[2] << 8), nlen = deflate[3] | (deflate[4] << 8);
    if ((len ^ 0xFFFFu) != nlen || deflate.size() != 5 + static_cast<std::size_t>(len)) return std::nullopt;
    return deflate.size() * 8;
  }
  if (type != 2) return std::nullopt;
  const std::optional<std::vector<int>> lengths = dynamic_literal_lengths(in);
  if (!lengths) return std::nullopt;
  CanonicalCode literal_code;
  const int eob_length = (*lengths)[256];
  if (eob_length == 0 || !literal_code.build(*lengths)) return std::nullopt;
  const int eob = literal_code.code_of(*lengths, 256);
  // The block ends with the end-of-block code, then zero bits to the byte. A
  // code with a 1 bit fits there at one place only: read at another, some 1
  // would fall in the padding, or the code would not match itself shifted.
  // Still, every place is tried, and only a single fit is taken.
  const std::size_t bits = in.size_bits();
  std::optional<std::size_t> end;
  for (std::size_t pad = 0; pad < 8 && pad <= bits; ++pad) {
    const std::size_t at = bits - pad;
    if (at < in.position() + static_cast<std::size_t>(eob_length)) break;
    bool fits = true;
    for (std::size_t i = at; i < bits && fits; ++i) fits = !in.bit(i);
    for (int i = 0; i < eob_length && fits; ++i)
      fits = in.bit(at - static_cast<std::size_t>(eob_length) + static_cast<std::size_t>(i)) ==
             static_cast<bool>((eob >> (eob_length - 1 - i)) & 1);
    if (!fits) continue;
    if (end) return std::nullopt;
    end = at;
  }
  return end;
}

namespace {

using Compressor = std::unique_ptr<libdeflate_compressor, decltype(&libdeflate_free_compressor)>;

// libdeflate's fastest level: zlib's took about twice as long on a
// megapixel render, and writes larger files.
Compressor fastest_compressor() {
  Compressor compressor(libdeflate_alloc_compressor(1), libdeflate_free_compressor);
  if (!compressor) throw std::bad_alloc();
  return compressor;
}

// The empty stored block that ends a band whose data ends `pad` (1 to 7) bits
// before its last byte's end: its three header bits (not final, stored) go
// into the padding if it has room, else into one more byte; then LEN = 0 and
// NLEN = 0xFFFF, byte-aligned.
constexpr std::array<unsigned char, 5> kRealign = {0x00, 0x00, 0x00, 0xFF, 0xFF};

std::size_t realign_bytes(std::size_t pad) {
  if (pad == 0) return 0;
  return pad >= 3 ? 4 : 5;
}

// The room a band of `size` bytes may take: libdeflate's bound or zlib's,
// with its full flush, whichever is larger, and the realigning block.
std::size_t band_room(std::size_t size) {
  const std::size_t libdeflate_bound = libdeflate_deflate_compress_bound(nullptr, size);
  const std::size_t zlib_bound = compressBound(static_cast<uLong>(size)) + 8;
  return std::max(libdeflate_bound, zlib_bound) + kRealign.size();
}

// One thread's compressors: libdeflate's, and zlib's for the bands whose end
// single_block_end cannot place.
class BandCompressor {
 public:
  BandCompressor() : libdeflate_(fastest_compressor()) {}
  BandCompressor(const BandCompressor&) = delete;
  BandCompressor& operator=(const BandCompressor&) = delete;
  ~BandCompressor() {
    if (zlib_ready_) deflateEnd(&zlib_);
  }

  // `in` as DEFLATE data in a copy of its own size; the last band ends the
  // stream, any other ends byte-aligned and not final. The data is first
  // written into this compressor's room, which serves every band it takes,
  // so only the copy touches new memory.
  std::pair<std::unique_ptr<unsigned char[]>, std::size_t> compress(std::span<const unsigned char> in, bool last) {
    const std::size_t room = band_room(in.size());
    if (room_size_ < room) {
      room_ = std::make_unique_for_overwrite<unsigned char[]>(room);
      room_size_ = room;
    }
    const std::size_t n = compress(in, {room_.get(), room}, last);
    auto data = std::make_unique_for_overwrite<unsigned char[]>(n);
    std::memcpy(data.get(), room_.get(), n);
    return {std::move(data), n};
  }

 private:
  // `in` as DEFLATE data into `out` (band_room(in.size()) bytes); returns the
  // bytes written.
  std::size_t compress(std::span<const unsigned char> in, std::span<unsigned char> out, bool last) {
    const std::size_t n = libdeflate_deflate_compress(libdeflate_.get(), in.data(), in.size(), out.data(), out.size());
    if (n == 0) throw std::logic_error("libdeflate: a band's room was too small");
    if (last) return n;
    if (const std::optional<std::size_t> end = single_block_end(out.first(n))) {
      out[0] &= 0xFE;  // no longer the final block
      const std::size_t extra = realign_bytes(n * 8 - *end);
      std::memcpy(out.data() + n, kRealign.data() + (kRealign.size() - extra), extra);
      return n + extra;
    }
    return compress_with_zlib(in, out);
  }

  std::size_t compress_with_zlib(std::span<const unsigned char> in, std::span<unsigned char> out) {
    if (!zlib_ready_) {
      zlib_ = z_stream{};
      if (deflateInit2(&zlib_, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) throw std::bad_alloc();
      zlib_ready_ = true;
    } else if (deflateReset(&zlib_) != Z_OK) {
      throw std::logic_error("zlib: deflateReset failed");
    }
    zlib_.next_in = const_cast<unsigned char*>(in.data());
    zlib_.avail_in = static_cast<uInt>(in.size());
    zlib_.next_out = out.data();
    zlib_.avail_out = static_cast<uInt>(out.size());
    if (deflate(&zlib_, Z_FULL_FLUSH) != Z_OK || zlib_.avail_in != 0 || zlib_.avail_out == 0)
      throw std::logic_error("zlib: a band's room was too small");
    return out.size() - zlib_.avail_out;
  }

  Compressor libdeflate_;
  z_stream zlib_{};
  bool zlib_ready_ = false;
  std::unique_ptr<unsigned char[]> room_;
  std::size_t room_size_ = 0;
};

}  // namespace

// Compressors for the threads compressing at a time, each made once and
// lent to one band at a time: libdeflate's tables are large, and a thread
// that keeps one hot compresses faster than one that makes its own.
class ZlibBandWriter::Compressors {
 public:
  std::unique_ptr<BandCompressor> take() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!idle_.empty()) {
        std::unique_ptr<BandCompressor> c = std::move(idle_.back());
        idle_.pop_back();
        return c;
      }
    }
    return std::make_unique<BandCompressor>();
  }
  void give_back(std::unique_ptr<BandCompressor> c) {
    const std::lock_guard<std::mutex> lock(mutex_);
    idle_.push_back(std::move(c));
  }

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<BandCompressor>> idle_;
};

ZlibBandWriter::ZlibBandWriter(std::uint64_t size, std::size_t band_bytes)
    : size_(size), band_bytes_(band_bytes), compressors_(std::make_unique<Compressors>()) {
  if (band_bytes == 0) throw std::logic_error("zlib bands of 0 bytes");
  const std::uint64_t bands = std::max<std::uint64_t>(1, (size + band_bytes - 1) / band_bytes);
  if (bands > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
    throw std::length_error("too many zlib bands");
  stream_.bands_.resize(bands);
  stream_.band_sizes_.resize(bands);
  adler_.resize(bands);
  compressed_.resize(bands);
}

ZlibBandWriter::~ZlibBandWriter() = default;

std::size_t ZlibBandWriter::band_size(std::size_t b) const {
  const std::uint64_t begin = static_cast<std::uint64_t>(b) * band_bytes_;
  return static_cast<std::size_t>(std::min<std::uint64_t>(band_bytes_, size_ - begin));
}

void ZlibBandWriter::compress(std::size_t b, std::span<const unsigned char> input) {
  if (b >= bands() || input.size() != band_size(b)) throw std::logic_error("zlib band: wrong band or size");
  std::unique_ptr<BandCompressor> compressor = compressors_->take();
  auto [data, n] = compressor->compress(input, b + 1 == bands());
  stream_.bands_[b] = std::move(data);
  stream_.band_sizes_[b] = n;
  adler_[b] = libdeflate_adler32(1, input.data(), input.size());
  compressed_[b] = 1;
  compressors_->give_back(std::move(compressor));
}

ZlibStream ZlibBandWriter::finish() {
  if (size_ == 0 && !compressed_[0]) compress(0, {});
  if (std::find(compressed_.begin(), compressed_.end(), 0) != compressed_.end())
    throw std::logic_error("zlib bands: a band was not compressed");
  uLong checksum = 1;
  for (std::size_t b = 0; b < bands(); ++b)
    checksum = adler32_combine(checksum, adler_[b], static_cast<z_off_t>(band_size(b)));
  for (std::size_t k = 0; k < 4; ++k) stream_.adler32_[k] = static_cast<unsigned char>(checksum >> (24 - 8 * k));
  return std::move(stream_);
}

std::size_t ZlibStream::size() const {
  std::size_t n = header_.size() + adler32_.size();
  for (const std::size_t s : band_sizes_) n += s;
  return n;
}

std::span<const unsigned char> ZlibStream::piece(std::size_t k) const {
  if (k == 0) return header_;
  if (k <= bands_.size()) return {bands_[k - 1].get(), band_sizes_[k - 1]};
  return adler32_;
}

std::vector<unsigned char> ZlibStream::joined() const {
  std::vector<unsigned char> out;
  out.reserve(size());
  for (std::size_t k = 0; k < pieces(); ++k) out.insert(out.end(), piece(k).begin(), piece(k).end());
  return out;
}

std::uint64_t zlib_compress_in_bands_memory(std::uint64_t size, std::size_t band_bytes) {
  const std::uint64_t whole = size / band_bytes, rest = size % band_bytes;
  return 6 + whole * band_room(band_bytes) + (rest != 0 || size == 0 ? band_room(rest) : 0);
}

ZlibStream zlib_compress_in_bands(std::span<const unsigned char> data, int threads, std::size_t band_bytes) {
  ZlibBandWriter writer(data.size(), band_bytes);
  parallel_rows(threads, static_cast<int>(writer.bands()), [&](const tbb::blocked_range<int>& range) {
    for (int i = range.begin(); i != range.end(); ++i) {
      const auto b = static_cast<std::size_t>(i);
      writer.compress(b, data.subspan(b * writer.band_bytes(), writer.band_size(b)));
    }
  });
  return writer.finish();
}

}  // namespace capsim
