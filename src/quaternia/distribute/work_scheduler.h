// Work handed out on demand over a channel (channel.h): items 0 .. n-1 (a poster's units, a
// film's frames) go, in order, to whichever rank asks first, so fast and slow items balance
// themselves with no static split. Rank 0 hands them out and takes the results; it also works
// through items on a thread of its own (LocalWorker) whenever that thread is free. A worker's
// result message says that it is free again, so each item costs one message each way.
//
// A worker the channel reports Lost in the middle of an item has that item handed out again (to
// the next free worker, rank 0's own thread included), and its summary is not awaited: every
// item's result is still taken exactly once.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "quaternia/distribute/channel.h"
#include "quaternia/scene/json.h"

namespace quaternia {

struct WorkItems {
    int64_t count = 0;
    // Does item `item` on this rank and returns its result message (rank 0's own items too):
    // never empty, but where the work was cancelled.
    std::function<std::vector<uint8_t>(int64_t item)> run;
    // Rank 0: whether `item` may be handed out now (a window of bands in memory); items wait
    // in order until it may.
    std::function<bool(int64_t item)> mayStart = [](int64_t) { return true; };
    // Rank 0, calling thread: a result from rank `source`, in the order they arrive.
    std::function<void(int source, const std::vector<uint8_t>& result)> take;
    // Rank 0: called after each result with the items done so far.
    std::function<void(int64_t done, int64_t count)> progress;
};

// What one rank did.
struct RankShare {
    int64_t items = 0;
    double busySeconds = 0;  // in run()
    int64_t peakResidentKiB = 0;
};

// Rank 0: hands out every item and takes every result; returns each rank's share (index =
// rank; a lost rank's is empty), or an empty vector when `cancel` was set first. Rethrows what
// rank 0's own run() or take() throws.
std::vector<RankShare> handOutWork(Channel& channel, const WorkItems& items,
                                   const std::atomic<bool>* cancel);
// Every other rank: asks for items and runs them until there are no more, then reports its
// share. False when `cancel` was set first (or this rank was lost).
bool workOnItems(Channel& channel, const WorkItems& items, const std::atomic<bool>* cancel);

// Each rank's share as JSON objects {rank, <itemsName>, render_seconds, peak_rss_kib}.
Json rankSharesJson(const std::vector<RankShare>& shares, const char* itemsName);

// This process's peak resident memory (getrusage), in KiB.
int64_t peakResidentKiB();

}  // namespace quaternia
