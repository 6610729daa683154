#include "quaternia/distribute/work_scheduler.h"

#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <stdexcept>
#include <thread>

#include "quaternia/distribute/scheduler_test_job.h"

namespace quaternia {
namespace {

using namespace std::chrono_literals;
using testing::expectEveryItemOnce;
using testing::JobOutcome;
using testing::randomDelays;
using testing::runJob;
using testing::Watchdog;
using testing::Work;

TEST(WorkScheduler, EveryItemRunsOnceAndEveryResultIsTakenOnce) {
    InProcessNetwork network(4);
    std::atomic<bool> cancel{false};
    Watchdog watchdog(cancel, 20s);
    const JobOutcome outcome = runJob(network, 60, randomDelays(), nullptr, cancel);
    ASSERT_FALSE(watchdog.disarm()) << "the job hung";
    expectEveryItemOnce(outcome, 60);
    for (int64_t item = 0; item < 60; ++item)
        EXPECT_EQ(outcome.runs.at(item), 1) << item;
    ASSERT_EQ(outcome.shares.size(), 4u);
    std::map<int, int64_t> takenFrom;
    for (const auto& [source, item] : outcome.taken)
        ++takenFrom[source];
    for (int rank = 0; rank < 4; ++rank) {
        // Each rank's summary counts what it did; with 60 items of up to 3 ms each, all work.
        EXPECT_EQ(outcome.shares[size_t(rank)].items, takenFrom[rank]) << rank;
        EXPECT_GT(outcome.shares[size_t(rank)].items, 0) << rank;
        EXPECT_GT(outcome.shares[size_t(rank)].peakResidentKiB, 0) << rank;
    }
    for (int rank = 1; rank < 4; ++rank)
        EXPECT_TRUE(outcome.workerFinished.at(rank)) << rank;
}

// An item starts only once mayStart allows it: here when the results taken come within `window`
// items of it. A window of 1 makes the items run one at a time, in order.
TEST(WorkScheduler, ItemsWaitForTheirWindow) {
    for (int64_t window : {1, 3}) {
        InProcessNetwork network(4);
        std::atomic<bool> cancel{false};
        Watchdog watchdog(cancel, 20s);
        std::atomic<int64_t> taken{0}, running{0}, mostRunning{0}, tooEarly{0};
        const Work work = [&, delays = randomDelays()](int rank, int64_t item) {
            if (item >= taken.load() + window) ++tooEarly;
            const int64_t now = ++running;
            int64_t most = mostRunning.load();
            while (now > most && !mostRunning.compare_exchange_weak(most, now)) {
            }
            delays(rank, item);
            --running;
        };
        const JobOutcome outcome = runJob(
            network, 30, work, [&](int64_t item) { return item < taken.load() + window; }, cancel,
            [&](int, int64_t) { ++taken; });
        ASSERT_FALSE(watchdog.disarm()) << "the job hung";
        expectEveryItemOnce(outcome, 30);
        EXPECT_EQ(tooEarly.load(), 0) << "window " << window;
        EXPECT_LE(mostRunning.load(), window);
        if (window == 1) {
            for (size_t at = 0; at < outcome.taken.size(); ++at)
                EXPECT_EQ(outcome.taken[at].second, int64_t(at));
        }
    }
}

// An error of rank 0's own item ends the job with that error.
TEST(WorkScheduler, RankZerosErrorIsRethrown) {
    InProcessNetwork network(2);
    std::atomic<bool> cancel{false};
    Watchdog watchdog(cancel, 20s);
    const Work work = [&](int rank, int64_t) {
        if (rank == 0) throw std::runtime_error("rank 0 failed");
        std::this_thread::sleep_for(1ms);
    };
    EXPECT_THROW(
        {
            try {
                runJob(network, 10, work, nullptr, cancel);
            } catch (const std::runtime_error& e) {
                EXPECT_STREQ(e.what(), "rank 0 failed");
                throw;
            }
        },
        std::runtime_error);
    EXPECT_FALSE(watchdog.disarm());
}

TEST(WorkScheduler, RankSharesAsJson) {
    const Json json = rankSharesJson({{4, 1.5, 2048}, {6, 2.5, 1024}}, "frames");
    ASSERT_EQ(json.size(), 2u);
    EXPECT_EQ(json[1]["rank"], 1);
    EXPECT_EQ(json[1]["frames"], 6);
    EXPECT_EQ(json[1]["render_seconds"], 2.5);
    EXPECT_EQ(json[0]["peak_rss_kib"], 2048);
}

}  // namespace
}  // namespace quaternia
