// A fast DEFLATE encoder (RFC 1951) for PNG's filtered scanlines: matches are runs of the byte
// before (distance 1) and nothing else, each block gets its own Huffman codes (or is stored
// when that is shorter). This is what zlib does at level 1 with the Z_RLE strategy, which
// suits Paeth-filtered renders (runs of zero residuals on flat colour, small residuals
// elsewhere), without zlib's general machinery: on a 1080p frame it is several times faster
// (BM_EncodePng) and the files are about as small.
#pragma once

#include <cstddef>
#include <cstdint>

namespace quaternia {

// The most bytes deflateRuns writes for `size` input bytes (the stored encoding's size, plus
// the block headers and the closing empty block).
size_t deflateRunsBound(size_t size);

// Writes the raw DEFLATE encoding of input[0, size) to `out` (which has deflateRunsBound(size)
// bytes of room) and returns the bytes written. `before` is the byte that came before the input
// in the stream (a run may continue it), or -1 where there is none. A `last` piece ends with
// the final block; any other ends on a byte boundary with an empty stored block (as zlib's
// Z_SYNC_FLUSH does), so that the next piece's encoding can follow it.
size_t deflateRuns(const uint8_t* input, size_t size, int before, bool last, uint8_t* out);

}  // namespace quaternia
