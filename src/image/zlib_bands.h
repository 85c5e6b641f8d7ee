#pragma once
// One zlib stream (RFC 1950) compressed as independent bands on several
// threads: what a PNG's image data must be, made by more than one core.
//
// The input is cut into bands of a fixed size, so the bytes never depend on
// the number of threads. libdeflate compresses each band on its own; every
// band but the last is then made to end on a byte boundary without being the
// stream's last block, so that the bands join by concatenation. libdeflate
// (1.14) cannot flush, and it marks its last block final, so that is done on
// its output: the final bit is cleared and an empty stored block (the bytes
// zlib's full flush writes) realigns the stream. Both need the bit where the
// band's data ends, which a band of one dynamic-Huffman block gives without
// decoding it (single_block_end); a stored block ends on a byte already. A
// band written otherwise, or whose end cannot be placed, is compressed by zlib
// with a full flush instead. Neither library's compressor picks its code by
// the processor, so the stream is the same for the same input on any host.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace capsim {

// Bytes of input per band: 48 KiB, just under 16 rows of a PNG 1,024 pixels
// wide (3,073 bytes a row, with its filter byte). libdeflate's fastest
// level writes an input this short as one block unless it finds 8,192
// matches in it (a match per 6 bytes), which the images rendered here do not
// come near; a band that does goes to zlib. Shorter bands would make that
// impossible (3 x 8,192 bytes, matches being 3 bytes or more) at 3 % more
// compressed data on the bench's lattices; longer ones pass the 8,192 there.
inline constexpr std::size_t kZlibBandBytes = 49152;

// A zlib stream held as its pieces in order: the 2-byte header (deflate, 32
// KiB window, the fastest level, as libdeflate's zlib writer gives it), each
// band's DEFLATE data, the Adler-32 of the input. A PNG writes the pieces into
// its image data chunk one after another, so no band's data is copied again
// to join them, and no buffer the size of the stream is touched.
class ZlibStream {
 public:
  std::size_t size() const;
  // Piece k of pieces(): no allocation, so a caller that may longjmp (libpng's
  // errors) holds nothing that needs destroying.
  std::size_t pieces() const { return bands_.size() + 2; }
  std::span<const unsigned char> piece(std::size_t k) const;
  std::vector<unsigned char> joined() const;

 private:
  friend class ZlibBandWriter;
  std::array<unsigned char, 2> header_{0x78, 0x01};
  std::vector<std::unique_ptr<unsigned char[]>> bands_;
  std::vector<std::size_t> band_sizes_;
  std::array<unsigned char, 4> adler32_{};
};

// One zlib stream of `size` bytes of input, compressed a band at a time as
// each band's input is whole, by whichever thread has it: so a caller that
// makes its input in pieces (a PNG's rows, as they are traced) needs to keep
// only the bands not yet whole. Each band's input is compressed alone, so the
// stream does not depend on the order the bands come in, nor on the threads.
class ZlibBandWriter {
 public:
  // band_bytes > 0; throws std::length_error for more bands than an int counts.
  explicit ZlibBandWriter(std::uint64_t size, std::size_t band_bytes = kZlibBandBytes);
  ~ZlibBandWriter();
  ZlibBandWriter(const ZlibBandWriter&) = delete;
  ZlibBandWriter& operator=(const ZlibBandWriter&) = delete;

  std::size_t band_bytes() const { return band_bytes_; }
  std::size_t bands() const { return compressed_.size(); }
  // Band b's bytes of input: band_bytes, or what is left for the last band.
  std::size_t band_size(std::size_t b) const;

  // Compresses band b from its band_size(b) bytes of input. Safe to call from
  // several threads at once for different bands; each band once.
  void compress(std::size_t b, std::span<const unsigned char> input);

  // The stream. Throws std::logic_error if some band with input was not
  // compressed. Once.
  ZlibStream finish();

 private:
  class Compressors;

  std::uint64_t size_;
  std::size_t band_bytes_;
  ZlibStream stream_;                      // each band's data, once compressed
  std::vector<std::uint32_t> adler_;       // Adler-32 of each band's input
  std::vector<unsigned char> compressed_;  // per band: 1 once compressed
  std::unique_ptr<Compressors> compressors_;
};

// `data` as one zlib stream (ZlibBandWriter's), compressed on `threads` host
// threads (0 = all); the bytes depend only on `data` and `band_bytes` (> 0).
// The form for an input held whole, which the tests take as the reference for
// the band-by-band writers.
ZlibStream zlib_compress_in_bands(std::span<const unsigned char> data, int threads,
                                  std::size_t band_bytes = kZlibBandBytes);

// The most memory zlib_compress_in_bands takes for `size` bytes of input: the
// compressed data's room.
std::uint64_t zlib_compress_in_bands_memory(std::uint64_t size, std::size_t band_bytes = kZlibBandBytes);

// Where a raw DEFLATE stream that is one final dynamic-Huffman block ends: the
// number of bits up to and including its end-of-block code, the rest of its
// last byte being the zero bits that pad it. A stored block that fills the
// stream ends with its last byte. Empty for anything else (several blocks, a
// fixed-Huffman block, a malformed header) and for the one case the padding
// leaves open: an end-of-block code of zero bits only, which would read the
// same at several places.
std::optional<std::size_t> single_block_end(std::span<const unsigned char> deflate);

}  // namespace capsim
