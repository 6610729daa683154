#include "quaternia/distribute/work_scheduler.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "quaternia/distribute/scheduler_test_job.h"

namespace quaternia {
namespace {

using namespace std::chrono_literals;
using testing::expectEveryItemOnce;
using testing::JobOutcome;
using testing::randomDelays;
using testing::runJob;
using testing::waitUntilSet;
using testing::Watchdog;
using testing::Work;

// A worker that dies in the middle of an item: the item is run again elsewhere, its result
// taken once, and the job ends without the dead rank's summary.
TEST(WorkScheduler, LostWorkersItemIsRedoneElsewhere) {
    InProcessNetwork network(4);
    std::atomic<bool> cancel{false};
    Watchdog watchdog(cancel, 20s);
    std::atomic<int64_t> lostItem{-1};
    const Work delays = randomDelays();
    const Work work = [&](int rank, int64_t item) {
        if (rank != 2) waitUntilSet(lostItem);  // every other rank busy: rank 2 gets an item
        delays(rank, item);
        int64_t none = -1;
        if (rank == 2 && lostItem.compare_exchange_strong(none, item)) network.lose(2);
    };
    const JobOutcome outcome = runJob(network, 40, work, nullptr, cancel);
    ASSERT_FALSE(watchdog.disarm()) << "the job hung";
    expectEveryItemOnce(outcome, 40);
    ASSERT_GE(lostItem.load(), 0);
    EXPECT_EQ(outcome.runs.at(lostItem.load()), 2);  // once on the dead rank, once again
    for (const auto& [source, item] : outcome.taken)
        EXPECT_NE(source, 2) << item;       // nothing was taken from the dead rank
    EXPECT_EQ(outcome.shares[2].items, 0);  // no summary from it
    EXPECT_FALSE(outcome.workerFinished.at(2));
    EXPECT_TRUE(outcome.workerFinished.at(1));
    EXPECT_TRUE(outcome.workerFinished.at(3));
}

// The only worker dies in the middle of its item: rank 0's own thread redoes it (the
// workers that could have are gone). A rank that dies before asking for work is not awaited.
TEST(WorkScheduler, RankZeroRedoesTheItemOfTheLastLostWorker) {
    InProcessNetwork network(3);
    network.lose(2);  // before it even says it is ready
    std::atomic<bool> cancel{false};
    Watchdog watchdog(cancel, 20s);
    std::atomic<int64_t> lostItem{-1};
    const Work work = [&](int rank, int64_t item) {
        if (rank == 0) waitUntilSet(lostItem);  // rank 0 busy: rank 1 gets an item
        if (rank == 1) {
            int64_t none = -1;
            if (lostItem.compare_exchange_strong(none, item)) {
                std::this_thread::sleep_for(5ms);  // rank 0 finishes the rest meanwhile
                network.lose(1);
            }
        }
    };
    const JobOutcome outcome = runJob(network, 6, work, nullptr, cancel);
    ASSERT_FALSE(watchdog.disarm()) << "the job hung";
    expectEveryItemOnce(outcome, 6);
    ASSERT_GE(lostItem.load(), 0);
    for (const auto& [source, item] : outcome.taken)
        EXPECT_EQ(source, 0) << item;
    EXPECT_EQ(outcome.shares[0].items, 6);  // its own 5 and the lost one again
    EXPECT_EQ(outcome.runs.at(lostItem.load()), 2);
    EXPECT_FALSE(outcome.workerFinished.at(1));
    EXPECT_FALSE(outcome.workerFinished.at(2));
}

// Cancelled in the middle of long items: every rank stops within a few of the items' polls.
TEST(WorkScheduler, CancellationReturnsPromptly) {
    InProcessNetwork network(3);
    std::atomic<bool> cancel{false};
    Watchdog watchdog(cancel, 20s);
    const Work work = [&](int, int64_t) {
        // A long item that, as a render does, looks at the flag as it goes.
        for (int step = 0; step < 2000 && !cancel.load(); ++step)
            std::this_thread::sleep_for(1ms);
    };
    std::thread canceller([&] {
        std::this_thread::sleep_for(50ms);
        cancel = true;
    });
    const auto start = std::chrono::steady_clock::now();
    const JobOutcome outcome = runJob(network, 100, work, nullptr, cancel);
    const auto took = std::chrono::steady_clock::now() - start;
    canceller.join();
    EXPECT_FALSE(watchdog.disarm());
    EXPECT_TRUE(outcome.shares.empty());
    EXPECT_LT(took, 1s);
    EXPECT_FALSE(outcome.workerFinished.at(1));
    EXPECT_FALSE(outcome.workerFinished.at(2));
}

}  // namespace
}  // namespace quaternia
