#include "quaternia/util/parallel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace quaternia {
namespace {

// Whether the closed rectangle of `tile` contains the image centre (width / 2, height / 2).
bool containsCentre(const Tile& tile, int width, int height) {
    return 2 * tile.x0 <= width && width <= 2 * tile.x1 && 2 * tile.y0 <= height &&
           height <= 2 * tile.y1;
}

TEST(Parallel, ResolveThreadCount) {
    const unsigned hardware = std::thread::hardware_concurrency();
    EXPECT_EQ(resolveThreadCount(0), hardware == 0 ? 1 : int(std::min(hardware, 1024u)));
    EXPECT_EQ(resolveThreadCount(1), 1);
    EXPECT_EQ(resolveThreadCount(7), 7);
    EXPECT_EQ(resolveThreadCount(1024), 1024);
    EXPECT_EQ(resolveThreadCount(5000), 1024);
    EXPECT_EQ(resolveThreadCount(-3), 1);
}

TEST(Parallel, TilesCoverEveryPixelOnceForOddSizes) {
    for (int threads : {1, 2, 7}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        const int width = 97, height = 61;
        std::vector<std::atomic<int>> visits(width * height);
        std::atomic<int> badThreadIndex{0};
        ParallelOptions options;
        options.threads = threads;
        options.tileSize = 16;
        bool completed = parallelForTiles(width, height, options, [&](const Tile& t, int index) {
            if (index < 0 || index >= threads) ++badThreadIndex;
            for (int y = t.y0; y < t.y1; ++y) {
                for (int x = t.x0; x < t.x1; ++x)
                    ++visits[y * width + x];
            }
        });
        EXPECT_TRUE(completed);
        EXPECT_EQ(badThreadIndex.load(), 0);
        int wrong = 0;
        for (const auto& v : visits)
            wrong += v.load() != 1;
        EXPECT_EQ(wrong, 0) << "pixels not visited exactly once";
    }
}

TEST(Parallel, CentreOutTilesPartitionTheImage) {
    std::vector<Tile> tiles = centreOutTiles(97, 61, 16);
    ASSERT_EQ(tiles.size(), 7u * 4u);  // ceil(97 / 16) x ceil(61 / 16)
    int64_t area = 0;
    for (const Tile& t : tiles) {
        EXPECT_LT(t.x0, t.x1);
        EXPECT_LT(t.y0, t.y1);
        EXPECT_LE(t.x1 - t.x0, 16);
        EXPECT_LE(t.y1 - t.y0, 16);
        EXPECT_EQ(t.x0 % 16, 0);
        EXPECT_EQ(t.y0 % 16, 0);
        area += int64_t(t.x1 - t.x0) * (t.y1 - t.y0);
    }
    EXPECT_EQ(area, 97 * 61);
    EXPECT_TRUE(centreOutTiles(0, 10, 16).empty());
    EXPECT_THROW(centreOutTiles(-1, 10, 16), std::invalid_argument);
    EXPECT_EQ(centreOutTiles(64, 64, 0).size(), 4u) << "tile size 0 means 32";
}

TEST(Parallel, CentreOutOrderWithOneThread) {
    struct Case {
        int width, height, tileSize;
    };
    for (Case c : {Case{97, 61, 16}, Case{64, 64, 32}, Case{40, 10, 16}, Case{320, 240, 32},
                   Case{33, 1, 1}}) {
        SCOPED_TRACE(std::to_string(c.width) + "x" + std::to_string(c.height) + " tile " +
                     std::to_string(c.tileSize));
        std::vector<Tile> order;
        ParallelOptions options;
        options.threads = 1;
        options.tileSize = c.tileSize;
        parallelForTiles(c.width, c.height, options, [&](const Tile& t, int index) {
            EXPECT_EQ(index, 0);
            order.push_back(t);
        });
        ASSERT_FALSE(order.empty());
        EXPECT_TRUE(containsCentre(order.front(), c.width, c.height))
            << "first tile " << order.front().x0 << "," << order.front().y0;
        // The distance from the centre to the tile never decreases along the order.
        auto distance = [&](const Tile& t) {
            auto gap = [](int lo, int hi, int point) {
                return std::max({lo - point, point - hi, 0});
            };
            const int64_t gx = gap(2 * t.x0, 2 * t.x1, c.width);
            const int64_t gy = gap(2 * t.y0, 2 * t.y1, c.height);
            return gx * gx + gy * gy;
        };
        for (size_t i = 1; i < order.size(); ++i)
            EXPECT_LE(distance(order[i - 1]), distance(order[i])) << "tile " << i;
    }
}

TEST(Parallel, CentreOutOrderOnAThreeByThreeGrid) {
    // 3 x 3 tiles of 10: centre first, then the 4 edge neighbours, then the 4 corners.
    std::vector<Tile> tiles = centreOutTiles(30, 30, 10);
    ASSERT_EQ(tiles.size(), 9u);
    EXPECT_EQ(tiles[0].x0, 10);
    EXPECT_EQ(tiles[0].y0, 10);
    for (int i = 1; i <= 4; ++i)
        EXPECT_TRUE(tiles[i].x0 == 10 || tiles[i].y0 == 10) << i;
    for (int i = 5; i <= 8; ++i)
        EXPECT_TRUE(tiles[i].x0 != 10 && tiles[i].y0 != 10) << i;
    // Ties are broken row-major: deterministic.
    EXPECT_EQ(tiles[1].y0, 0);
    EXPECT_EQ(tiles[1].x0, 10);
    EXPECT_EQ(tiles[5].y0, 0);
    EXPECT_EQ(tiles[5].x0, 0);
}

TEST(Parallel, CancellationFromInsideTheBodyStopsEarly) {
    for (int threads : {1, 2, 7}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        std::atomic<bool> cancel{false};
        std::atomic<int> ran{0};
        ParallelOptions options;
        options.threads = threads;
        options.tileSize = 4;
        options.cancel = &cancel;
        bool completed = parallelForTiles(64, 64, options, [&](const Tile&, int) {
            if (++ran == 5) cancel = true;
        });
        EXPECT_FALSE(completed);
        // Each worker may be inside one tile when the flag goes up, no more.
        EXPECT_GE(ran.load(), 5);
        EXPECT_LE(ran.load(), 5 + threads - 1);
    }
}

TEST(Parallel, CancelledBeforeStartRunsNothing) {
    std::atomic<bool> cancel{true};
    ParallelOptions options;
    options.threads = 3;
    options.cancel = &cancel;
    std::atomic<int> ran{0};
    EXPECT_FALSE(parallelForTiles(100, 100, options, [&](const Tile&, int) { ++ran; }));
    EXPECT_FALSE(parallelFor(1000, options, [&](int64_t, int64_t, int) { ++ran; }));
    EXPECT_EQ(ran.load(), 0);
}

TEST(Parallel, CancelAfterTheLastTileStillCompletes) {
    std::atomic<bool> cancel{false};
    ParallelOptions options;
    options.threads = 1;
    options.tileSize = 8;
    options.cancel = &cancel;
    int ran = 0;
    const int tiles = int(centreOutTiles(16, 16, 8).size());
    EXPECT_TRUE(parallelForTiles(16, 16, options, [&](const Tile&, int) {
        if (++ran == tiles) cancel = true;
    }));
}

TEST(Parallel, ProgressIsSerialisedMonotonicAndReachesTotal) {
    for (int threads : {1, 2, 7}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        std::vector<int64_t> reported;
        std::atomic<int> inside{0};
        bool overlapped = false;
        int64_t seenTotal = -1;
        ParallelOptions options;
        options.threads = threads;
        options.tileSize = 8;
        options.progress = [&](int64_t done, int64_t total) {
            if (++inside != 1) overlapped = true;
            reported.push_back(done);
            seenTotal = total;
            std::this_thread::yield();
            --inside;
        };
        EXPECT_TRUE(parallelForTiles(50, 30, options, [](const Tile&, int) {}));
        const int64_t total = 7 * 4;
        EXPECT_FALSE(overlapped);
        EXPECT_EQ(seenTotal, total);
        ASSERT_EQ(int64_t(reported.size()), total);
        for (size_t i = 0; i < reported.size(); ++i)
            EXPECT_EQ(reported[i], int64_t(i) + 1);
    }
}

TEST(Parallel, ExceptionPropagatesAfterWorkersJoin) {
    for (int threads : {1, 2, 7}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        std::atomic<int> ran{0}, active{0};
        ParallelOptions options;
        options.threads = threads;
        options.tileSize = 4;  // 256 tiles
        auto body = [&](const Tile&, int) {
            ++active;
            if (++ran == 3) {
                --active;
                throw std::runtime_error("tile failed");
            }
            // Slow tiles, so that the other workers cannot finish all 256 while the exception
            // unwinds (the skip only starts once it is caught).
            if (threads > 1) std::this_thread::sleep_for(std::chrono::milliseconds(1));
            --active;
        };
        EXPECT_THROW(parallelForTiles(64, 64, options, body), std::runtime_error);
        EXPECT_EQ(active.load(), 0) << "every worker stopped before the rethrow";
        if (threads == 1)
            EXPECT_EQ(ran.load(), 3) << "remaining tiles are skipped";
        else
            EXPECT_LT(ran.load(), 256) << "remaining tiles are skipped";
        EXPECT_THROW(parallelFor(1000, options,
                                 [&](int64_t begin, int64_t, int) {
                                     if (begin == 0) throw std::logic_error("chunk failed");
                                 }),
                     std::logic_error);
    }
}

TEST(Parallel, OneExceptionIsRethrownWhenSeveralWorkersThrow) {
    ParallelOptions options;
    options.threads = 4;
    options.tileSize = 1;
    try {
        parallelForTiles(8, 8, options, [](const Tile&, int) { throw std::out_of_range("x"); });
        FAIL() << "nothing thrown";
    } catch (const std::out_of_range&) {
    }
}

TEST(Parallel, ThrowingProgressPropagates) {
    ParallelOptions options;
    options.threads = 2;
    options.progress = [](int64_t done, int64_t total) {
        if (done < total) throw std::runtime_error("progress failed");
    };
    EXPECT_THROW(parallelFor(100, options, [](int64_t, int64_t, int) {}), std::runtime_error);
}

TEST(Parallel, ForCoversTheRangeOnceInChunks) {
    for (int threads : {1, 2, 7}) {
        for (int64_t count : {int64_t(0), int64_t(1), int64_t(13), int64_t(1000)}) {
            SCOPED_TRACE("threads " + std::to_string(threads) + ", count " + std::to_string(count));
            std::vector<std::atomic<int>> visits(static_cast<size_t>(count));
            std::mutex chunksMutex;
            int64_t chunks = 0, largest = 0;
            ParallelOptions options;
            options.threads = threads;
            EXPECT_TRUE(parallelFor(count, options, [&](int64_t begin, int64_t end, int index) {
                EXPECT_GE(index, 0);
                EXPECT_LT(index, threads);
                EXPECT_LT(begin, end);
                for (int64_t i = begin; i < end; ++i)
                    ++visits[size_t(i)];
                std::lock_guard lock(chunksMutex);
                ++chunks;
                largest = std::max(largest, end - begin);
            }));
            for (const auto& v : visits)
                EXPECT_EQ(v.load(), 1);
            // Automatic chunks: ceil(count / (8 * threads)) items each.
            const int64_t chunk = std::max<int64_t>(1, (count + 8 * threads - 1) / (8 * threads));
            EXPECT_EQ(largest, count == 0 ? 0 : chunk);
            EXPECT_EQ(chunks, (count + chunk - 1) / chunk);
        }
    }
}

TEST(Parallel, ForHonoursChunkSizeAndReportsItems) {
    ParallelOptions options;
    options.threads = 1;
    options.chunkSize = 30;
    std::vector<std::pair<int64_t, int64_t>> ranges;
    std::vector<int64_t> reported;
    options.progress = [&](int64_t done, int64_t total) {
        EXPECT_EQ(total, 100);
        reported.push_back(done);
    };
    parallelFor(100, options,
                [&](int64_t begin, int64_t end, int) { ranges.emplace_back(begin, end); });
    EXPECT_EQ(ranges,
              (std::vector<std::pair<int64_t, int64_t>>{{0, 30}, {30, 60}, {60, 90}, {90, 100}}));
    EXPECT_EQ(reported, (std::vector<int64_t>{30, 60, 90, 100}));
    EXPECT_THROW(parallelFor(-1, options, [](int64_t, int64_t, int) {}), std::invalid_argument);
}

TEST(Parallel, WorkersRunConcurrentlyOnTheCallingThreadAndOthers) {
    // With 2 threads and 2 items, both items must run at once: each waits for the other.
    ParallelOptions options;
    options.threads = 2;
    options.chunkSize = 1;
    std::atomic<int> arrived{0};
    std::vector<std::thread::id> ids(2);
    const std::thread::id caller = std::this_thread::get_id();
    parallelFor(2, options, [&](int64_t, int64_t, int index) {
        ids[size_t(index)] = std::this_thread::get_id();
        ++arrived;
        while (arrived.load() < 2)
            std::this_thread::yield();
    });
    EXPECT_EQ(ids[0], caller) << "the calling thread is worker 0";
    EXPECT_NE(ids[1], caller);
}

// Runs 3 items on 3 workers that wait for each other (so each worker takes one), and returns
// the thread of each worker.
std::vector<std::thread::id> threadsOfThreeWorkers() {
    ParallelOptions options;
    options.threads = 3;
    options.chunkSize = 1;
    std::atomic<int> arrived{0};
    std::vector<std::thread::id> ids(3);
    parallelFor(3, options, [&](int64_t, int64_t, int index) {
        ids[size_t(index)] = std::this_thread::get_id();
        ++arrived;
        while (arrived.load() < 3)
            std::this_thread::yield();
    });
    return ids;
}

TEST(Parallel, WorkersStayBetweenCalls) {
    // The same threads serve the next call: a film starts its workers once, not per frame.
    std::vector<std::thread::id> first = threadsOfThreeWorkers();
    std::vector<std::thread::id> second = threadsOfThreeWorkers();
    EXPECT_EQ(first, second);
    EXPECT_NE(first[1], first[2]);
}

TEST(Parallel, CallsFromSeveralThreadsAndFromInsideABodyEachRunWhole) {
    // One call holds the pool; the others (another thread's, a body's own) start threads of
    // their own and keep every rule: every item once, threadIndex in range.
    ParallelOptions options;
    options.threads = 3;
    options.chunkSize = 1;
    auto sumTo = [&](int64_t count) {
        std::atomic<int64_t> sum{0};
        parallelFor(count, options, [&](int64_t begin, int64_t end, int index) {
            EXPECT_TRUE(index >= 0 && index < 3);
            for (int64_t i = begin; i < end; ++i)
                sum += i;
        });
        return sum.load();
    };
    std::vector<std::thread> callers;
    std::atomic<int> correct{0};
    for (int t = 0; t < 4; ++t)
        callers.emplace_back([&] {
            for (int repeat = 0; repeat < 20; ++repeat) {
                std::atomic<int64_t> nested{0};
                parallelFor(4, options, [&](int64_t, int64_t, int) { nested += sumTo(100); });
                if (nested == 4 * 4950 && sumTo(1000) == 499500) ++correct;
            }
        });
    for (std::thread& caller : callers)
        caller.join();
    EXPECT_EQ(correct.load(), 80);
}

TEST(Parallel, EmptyWorkCompletesWithoutCallingAnything) {
    ParallelOptions options;
    options.progress = [](int64_t, int64_t) { ADD_FAILURE() << "progress called"; };
    EXPECT_TRUE(parallelForTiles(0, 0, options, [](const Tile&, int) { ADD_FAILURE(); }));
    EXPECT_TRUE(parallelFor(0, options, [](int64_t, int64_t, int) { ADD_FAILURE(); }));
}

}  // namespace
}  // namespace quaternia
