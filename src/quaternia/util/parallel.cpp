#include "quaternia/util/parallel.h"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

namespace quaternia {

namespace {

constexpr int kDefaultTileSize = 32;
constexpr int kMaxThreads = 1024;

// Threads that stay between calls, so that a film or a live explorer does not start a thread
// per worker per frame: pool thread k runs worker k of a call (the calling thread is worker 0).
// One call at a time holds the pool; tryRun refuses while another holds it, and the caller then
// starts threads of its own. The pool is never destroyed: its idle threads wait until the
// process ends, and nothing at exit has to wait for them.
class WorkerPool {
  public:
    static WorkerPool& instance() {
        static WorkerPool* pool = new WorkerPool;
        return *pool;
    }

    // Runs work(0) here and work(1 .. workers - 1) on pool threads (fewer where no more threads
    // can be started; `work` takes the items off one counter, so fewer workers still do all of
    // them), and returns true once every one has returned; false, running nothing, when the
    // pool is busy. `work` must not throw.
    bool tryRun(int workers, const std::function<void(int)>& work) {
        std::unique_lock hold(busy_, std::try_to_lock);
        if (!hold.owns_lock()) return false;
        std::unique_lock lock(mutex_);
        while (int(threads_.size()) < workers - 1) {
            try {
                threads_.emplace_back([this, index = int(threads_.size()) + 1, seen = generation_] {
                    serve(index, seen);
                });
            } catch (const std::system_error&) {
                break;
            }
        }
        job_ = &work;
        jobWorkers_ = std::min(workers, int(threads_.size()) + 1);
        running_ = jobWorkers_ - 1;
        ++generation_;
        lock.unlock();
        wake_.notify_all();
        work(0);
        lock.lock();
        done_.wait(lock, [&] { return running_ == 0; });
        job_ = nullptr;
        return true;
    }

  private:
    void serve(int index, uint64_t seen) {
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return generation_ != seen; });
            seen = generation_;
            if (index >= jobWorkers_) continue;
            const std::function<void(int)>& work = *job_;
            lock.unlock();
            work(index);
            lock.lock();
            if (--running_ == 0) done_.notify_one();
        }
    }

    std::mutex busy_;   // held by the call whose job runs
    std::mutex mutex_;  // guards the rest
    std::condition_variable wake_, done_;
    std::vector<std::thread> threads_;
    const std::function<void(int)>* job_ = nullptr;
    int jobWorkers_ = 0;
    int running_ = 0;  // pool threads still in the job
    uint64_t generation_ = 0;
};

// The worker machinery both parallel-fors share: items 0 .. itemCount - 1 go out in order
// through one atomic counter; runItem(item, threadIndex) runs one and returns its weight in
// progress units, which add up to progressTotal.
bool runItems(int64_t itemCount, int64_t progressTotal, const ParallelOptions& options,
              const std::function<int64_t(int64_t item, int threadIndex)>& runItem) {
    if (itemCount == 0) return true;
    const int workers = int(std::min<int64_t>(resolveThreadCount(options.threads), itemCount));

    std::atomic<int64_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr firstError;  // written by the first failing worker only, read after join
    std::mutex progressMutex;       // serialises the progress callback, and orders its counts
    int64_t progressDone = 0;

    auto cancelled = [&] {
        return options.cancel != nullptr && options.cancel->load(std::memory_order_acquire);
    };
    auto work = [&](int threadIndex) {
        try {
            while (!failed.load(std::memory_order_relaxed) && !cancelled()) {
                const int64_t item = next.fetch_add(1, std::memory_order_relaxed);
                if (item >= itemCount) break;
                const int64_t weight = runItem(item, threadIndex);
                if (options.progress) {
                    std::lock_guard lock(progressMutex);
                    progressDone += weight;
                    options.progress(progressDone, progressTotal);
                }
            }
        } catch (...) {
            if (!failed.exchange(true)) firstError = std::current_exception();
        }
    };

    if (!WorkerPool::instance().tryRun(workers, work)) {
        // The pool is busy (another thread's call, or a call from inside a body): this call
        // starts threads of its own.
        std::vector<std::thread> threads;
        threads.reserve(size_t(workers - 1));
        for (int threadIndex = 1; threadIndex < workers; ++threadIndex) {
            try {
                threads.emplace_back(work, threadIndex);
            } catch (const std::system_error&) {
                break;  // no more threads to be had: the ones running share the work
            }
        }
        work(0);
        for (std::thread& thread : threads)
            thread.join();
    }

    if (firstError) std::rethrow_exception(firstError);
    // Every item handed out ran, so all ran exactly when the counter went past the last one.
    return next.load() >= itemCount;
}

}  // namespace

int resolveThreadCount(int requested) {
    if (requested == 0) {
        const unsigned hardware = std::thread::hardware_concurrency();
        requested = hardware == 0 ? 1 : int(std::min<unsigned>(hardware, kMaxThreads));
    }
    return std::clamp(requested, 1, kMaxThreads);
}

std::vector<Tile> centreOutTiles(int width, int height, int tileSize) {
    if (width < 0 || height < 0)
        throw std::invalid_argument("cannot tile a negative image size " + std::to_string(width) +
                                    "x" + std::to_string(height));
    if (tileSize <= 0) tileSize = kDefaultTileSize;

    struct Keyed {
        double toTile, toCentre;  // squared, in units of half pixels
        Tile tile;
    };
    std::vector<Keyed> keyed;
    keyed.reserve(size_t((width + int64_t(tileSize) - 1) / tileSize) *
                  size_t((height + int64_t(tileSize) - 1) / tileSize));
    // Coordinates are doubled so that the image centre (width / 2, height / 2) and the tile
    // centres are integers.
    auto gap = [](int64_t lo, int64_t hi, int64_t point) {
        return double(std::max({lo - point, point - hi, int64_t(0)}));
    };
    for (int y0 = 0; y0 < height; y0 += std::min(tileSize, height - y0)) {
        const int y1 = y0 + std::min(tileSize, height - y0);
        for (int x0 = 0; x0 < width; x0 += std::min(tileSize, width - x0)) {
            const int x1 = x0 + std::min(tileSize, width - x0);
            const double gx = gap(2 * int64_t(x0), 2 * int64_t(x1), width);
            const double gy = gap(2 * int64_t(y0), 2 * int64_t(y1), height);
            const double cx = double(int64_t(x0) + x1 - width);
            const double cy = double(int64_t(y0) + y1 - height);
            keyed.push_back({gx * gx + gy * gy, cx * cx + cy * cy, Tile{x0, y0, x1, y1}});
        }
    }
    std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
        if (a.toTile != b.toTile) return a.toTile < b.toTile;
        if (a.toCentre != b.toCentre) return a.toCentre < b.toCentre;
        if (a.tile.y0 != b.tile.y0) return a.tile.y0 < b.tile.y0;
        return a.tile.x0 < b.tile.x0;
    });
    std::vector<Tile> tiles;
    tiles.reserve(keyed.size());
    for (const Keyed& k : keyed)
        tiles.push_back(k.tile);
    return tiles;
}

bool parallelForTiles(int width, int height, const ParallelOptions& options,
                      const std::function<void(const Tile&, int threadIndex)>& body) {
    const std::vector<Tile> tiles = centreOutTiles(width, height, options.tileSize);
    const int64_t count = int64_t(tiles.size());
    return runItems(count, count, options, [&](int64_t item, int threadIndex) -> int64_t {
        body(tiles[size_t(item)], threadIndex);
        return 1;
    });
}

bool parallelFor(int64_t count, const ParallelOptions& options,
                 const std::function<void(int64_t begin, int64_t end, int threadIndex)>& body) {
    if (count < 0)
        throw std::invalid_argument("parallelFor over a negative count " + std::to_string(count));
    int64_t chunk = options.chunkSize;
    if (chunk <= 0) {
        const int64_t target = 8 * int64_t(resolveThreadCount(options.threads));
        chunk = std::max<int64_t>(1, count / target + (count % target != 0));
    }
    const int64_t chunks = count / chunk + (count % chunk != 0);
    return runItems(chunks, count, options, [&](int64_t item, int threadIndex) -> int64_t {
        const int64_t begin = item * chunk;
        const int64_t end = std::min(count, begin + chunk);
        body(begin, end, threadIndex);
        return end - begin;
    });
}

}  // namespace quaternia
