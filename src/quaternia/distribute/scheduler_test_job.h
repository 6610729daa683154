// What the work scheduler's tests share: a job run over an InProcessNetwork, rank 0 on the
// calling thread and every worker on a thread of its own, and what came of it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <thread>
#include <utility>
#include <vector>

#include "quaternia/distribute/in_process_channel.h"
#include "quaternia/distribute/work_scheduler.h"

namespace quaternia::testing {

using namespace std::chrono_literals;

// Sets `cancel` after `limit` unless disarmed first: a job that would hang fails instead.
class Watchdog {
  public:
    Watchdog(std::atomic<bool>& cancel, std::chrono::milliseconds limit)
        : thread_([this, &cancel, limit] {
              std::unique_lock lock(mutex_);
              if (!disarmed_.wait_for(lock, limit, [this] { return done_; })) {
                  fired_ = true;
                  cancel = true;
              }
          }) {}
    ~Watchdog() { disarm(); }
    // Stops the watch; true if it had fired.
    bool disarm() {
        {
            std::lock_guard lock(mutex_);
            done_ = true;
        }
        disarmed_.notify_all();
        if (thread_.joinable()) thread_.join();
        return fired_;
    }

  private:
    std::mutex mutex_;
    std::condition_variable disarmed_;
    bool done_ = false, fired_ = false;
    std::thread thread_;
};

// A job's items, run anywhere: `work(rank, item)` does one, its result is the item's number.
using Work = std::function<void(int rank, int64_t item)>;

struct JobOutcome {
    std::vector<RankShare> shares;               // handOutWork's answer
    std::vector<std::pair<int, int64_t>> taken;  // (source, item) in the order taken
    std::map<int, bool> workerFinished;          // workOnItems' answer, by rank
    std::map<int64_t, int> runs;                 // how often each item was run
};

// Runs a job of `count` items on every rank of `network`: rank 0 (scheduler and local
// worker) on this thread, each other rank on a thread of its own.
inline JobOutcome runJob(InProcessNetwork& network, int64_t count, const Work& work,
                         std::function<bool(int64_t)> mayStart, std::atomic<bool>& cancel,
                         std::function<void(int, int64_t)> onTake = nullptr) {
    JobOutcome outcome;
    std::mutex mutex;  // outcome.runs and workerFinished, from every rank's thread
    auto itemsFor = [&](int rank) {
        WorkItems items;
        items.count = count;
        items.run = [&, rank](int64_t item) {
            {
                std::lock_guard lock(mutex);
                ++outcome.runs[item];
            }
            work(rank, item);
            if (cancel.load()) return std::vector<uint8_t>();
            return MessageWriter().put(item).bytes();
        };
        return items;
    };
    std::vector<std::thread> workers;
    for (int rank = 1; rank < network.size(); ++rank)
        workers.emplace_back([&, rank] {
            const WorkItems items = itemsFor(rank);
            const bool finished = workOnItems(network.channel(rank), items, &cancel);
            std::lock_guard lock(mutex);
            outcome.workerFinished[rank] = finished;
        });
    WorkItems items = itemsFor(0);
    if (mayStart) items.mayStart = mayStart;
    items.take = [&](int source, const std::vector<uint8_t>& result) {
        const int64_t item = MessageReader(result).get<int64_t>();
        outcome.taken.emplace_back(source, item);
        if (onTake) onTake(source, item);
    };
    try {
        outcome.shares = handOutWork(network.channel(0), items, &cancel);
    } catch (...) {
        cancel = true;  // the workers wait for work that will not come
        for (std::thread& worker : workers)
            worker.join();
        throw;
    }
    for (std::thread& worker : workers)
        worker.join();
    return outcome;
}

// Waits (up to a second) until `flag` is at least 0: a rank that lets another take an item.
inline void waitUntilSet(const std::atomic<int64_t>& flag) {
    const auto start = std::chrono::steady_clock::now();
    while (flag.load() < 0 && std::chrono::steady_clock::now() - start < 1s)
        std::this_thread::sleep_for(100us);
}

// Sleeps a random 0-3 ms, different for each rank, so that results come back in any order.
inline Work randomDelays() {
    auto engines = std::make_shared<std::vector<std::mt19937>>();
    for (int rank = 0; rank < 16; ++rank)
        engines->emplace_back(1234 + rank);
    return [engines](int rank, int64_t) {
        const int micros = std::uniform_int_distribution<int>(0, 3000)((*engines)[size_t(rank)]);
        std::this_thread::sleep_for(std::chrono::microseconds(micros));
    };
}

inline void expectEveryItemOnce(const JobOutcome& outcome, int64_t count) {
    std::vector<int64_t> items;
    for (const auto& [source, item] : outcome.taken)
        items.push_back(item);
    std::sort(items.begin(), items.end());
    std::vector<int64_t> expected(static_cast<size_t>(count));
    for (int64_t item = 0; item < count; ++item)
        expected[size_t(item)] = item;
    EXPECT_EQ(items, expected);  // each result taken exactly once
}

}  // namespace quaternia::testing
