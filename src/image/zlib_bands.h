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

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

namespace capsim {

// Bytes of input per band: 48 KiB, just under 16 rows of a PNG 1,024 pixels
// wide (3,073 bytes a row, with its filter byte). libdeflate's fastest
// level writes an input this short as one block unless it finds 8,192
// matches in it (a match per 6 bytes), which the images rendered here do not
// come near; a band that does goes to zlib. Shorter bands would make that
// impossible (3 x 8,192 bytes, matches being 3 bytes or more) at 3 % more
// compressed data on the bench's lattices; longer ones pass the 8,192 there.
inline constexpr std::size_t kZlibBandBytes = 49152;

struct ZlibStream {
  std::unique_ptr<unsigned char[]> bytes;
  std::size_t size = 0;
  std::span<const unsigned char> span() const { return {bytes.get(), size}; }
};

// `data` as one zlib stream: header 78 01, the bands' DEFLATE data, the
// Adler-32 of `data`. Compressed on `threads` host threads (0 = all); the
// bytes depend only on `data` and `band_bytes` (> 0).
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
