// The one parallel-for of Quaternia: the renderer, the mesher and the live explorer all run
// through it. Work is cut into items up front (tiles of an image, or chunks of a range) and
// handed out through one atomic counter to `threads` workers, the calling thread being worker
// 0, so that uneven items (a tile of sky next to a tile of fractal) balance themselves.
//
// Both functions share these rules:
// - cancellation: `cancel` is read before each item; once it is set, items not started are
//   skipped and the call returns false. It returns true when every item ran (also when the
//   flag was set after the last one started, and when there was nothing to do).
// - progress: after each finished item, `progress(done, total)` is called from whichever
//   worker finished it, serialised (never two at once) and with `done` increasing, so the
//   last call reports done == total unless the run was cancelled or failed.
// - exceptions: when a body (or the progress callback) throws, items not started are
//   skipped, and the first exception is rethrown on the calling thread once all workers have
//   stopped.
// - threadIndex is in [0, resolveThreadCount(options.threads)): index per-thread scratch
//   space with it. Fewer workers run when there are fewer items than threads.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace quaternia {

// Pixels [x0, x1) x [y0, y1).
struct Tile {
    int x0, y0, x1, y1;
};

// What a caller hands any long job (a render, a plane image, a mesh): how many threads, a flag
// that cancels it, and a progress callback taking the fraction done (serialised calls).
struct WorkOptions {
    int threads = 0;  // 0 = every core
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(double fraction)> progress;
};

struct ParallelOptions {
    int threads = 0;    // 0 = std::thread::hardware_concurrency(); see resolveThreadCount
    int tileSize = 32;  // side of the square tiles of parallelForTiles; <= 0 means 32
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(int64_t done, int64_t total)> progress;
    // Items per chunk of parallelFor; 0 chooses count / (8 * threads) rounded up, so each
    // worker takes about 8 chunks and uneven work balances. Ignored by parallelForTiles.
    int64_t chunkSize = 0;
};

// 0 means std::thread::hardware_concurrency() (1 where that is unknown); any other value is
// clamped to [1, 1024].
int resolveThreadCount(int requested);

// The tiles of a width x height image, each pixel in exactly one, in centre-out order: by the
// distance from the image centre to the tile (so the first tile contains the centre), then by
// the distance between the centres, then row-major. Throws std::invalid_argument for a
// negative size.
std::vector<Tile> centreOutTiles(int width, int height, int tileSize);

// Runs body(tile, threadIndex) once for each tile of centreOutTiles(width, height, tileSize),
// handed out in that order. Progress counts tiles.
bool parallelForTiles(int width, int height, const ParallelOptions& options,
                      const std::function<void(const Tile&, int threadIndex)>& body);

// Runs body(begin, end, threadIndex) over chunks [begin, end) that cover [0, count) exactly
// once, in increasing order of begin (options.chunkSize). Progress counts items, so it ends
// at (count, count). Throws std::invalid_argument for a negative count.
bool parallelFor(int64_t count, const ParallelOptions& options,
                 const std::function<void(int64_t begin, int64_t end, int threadIndex)>& body);

}  // namespace quaternia
