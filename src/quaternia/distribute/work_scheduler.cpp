#include "quaternia/distribute/work_scheduler.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <optional>
#include <set>
#include <thread>

#include "quaternia/distribute/local_worker.h"

namespace quaternia {
namespace {

std::vector<uint8_t> itemMessage(int64_t item) {
    return MessageWriter().put(item).bytes();
}

// Rank 0's book of the items: which come next, which are out with which worker, and which
// workers are still awaited.
class WorkBook {
  public:
    WorkBook(const WorkItems& items, int ranks)
        : items_(items), inFlight_(size_t(ranks)), awaited_(size_t(ranks), true) {
        awaited_[0] = false;  // rank 0 is the scheduler itself
        workersAwaited_ = ranks - 1;
    }

    // Whether an item may be handed out now. A lost worker's items come first, lowest first:
    // they are older than any not yet handed out, and a window of bands waits for them.
    bool itemReady() const {
        if (!redo_.empty()) return items_.mayStart(*redo_.begin());
        return next_ < items_.count && items_.mayStart(next_);
    }
    int64_t takeItem(int rank) {
        int64_t item;
        if (!redo_.empty()) {
            item = *redo_.begin();
            redo_.erase(redo_.begin());
        } else {
            item = next_++;
        }
        if (rank != 0) inFlight_[size_t(rank)] = item;
        return item;
    }
    // Every item handed out (and none to be handed out again): free workers may go.
    bool allHandedOut() const { return next_ == items_.count && redo_.empty(); }

    void resultFrom(int rank) { inFlight_[size_t(rank)].reset(); }
    void summaryFrom(int rank) { forget(rank); }
    // The rank's item, if it had one, is to be handed out again; its summary is not awaited.
    void lost(int rank) {
        if (auto& item = inFlight_[size_t(rank)]) redo_.insert(*item);
        inFlight_[size_t(rank)].reset();
        lost_.insert(rank);
        forget(rank);
    }
    bool isLost(int rank) const { return lost_.count(rank) != 0; }
    int workersAwaited() const { return workersAwaited_; }

  private:
    void forget(int rank) {
        if (awaited_[size_t(rank)]) --workersAwaited_;
        awaited_[size_t(rank)] = false;
    }

    const WorkItems& items_;
    int64_t next_ = 0;
    std::set<int64_t> redo_;
    std::vector<std::optional<int64_t>> inFlight_;  // by rank: the item a worker is running
    std::vector<bool> awaited_;                     // by rank: its summary is still to come
    std::set<int> lost_;
    int workersAwaited_ = 0;
};

}  // namespace

Json rankSharesJson(const std::vector<RankShare>& shares, const char* itemsName) {
    Json ranks = Json::array();
    for (size_t rank = 0; rank < shares.size(); ++rank) {
        Json share;
        share["rank"] = rank;
        share[itemsName] = shares[rank].items;
        share["render_seconds"] = shares[rank].busySeconds;
        share["peak_rss_kib"] = shares[rank].peakResidentKiB;
        ranks.push_back(share);
    }
    return ranks;
}

int64_t peakResidentKiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return int64_t(usage.ru_maxrss);  // KiB on Linux
}

std::vector<RankShare> handOutWork(Channel& channel, const WorkItems& items,
                                   const std::atomic<bool>* cancel) {
    std::vector<RankShare> shares(size_t(channel.size()));
    WorkBook book(items, channel.size());
    LocalWorker local(items);
    std::deque<int> waiting;  // ranks free for work, first come first served
    int64_t done = 0;
    auto finished = [&](int source, const std::vector<uint8_t>& result) {
        items.take(source, result);
        ++done;
        if (items.progress) items.progress(done, items.count);
    };
    while (done < items.count || book.workersAwaited() > 0) {
        if (cancel != nullptr && cancel->load()) return {};
        bool busy = false;
        while (auto message = channel.poll(cancel)) {
            busy = true;
            const int source = message->source;
            if (book.isLost(source)) continue;  // nothing is taken from a rank once it is lost
            switch (message->tag) {
                case MessageTag::Summary:
                    shares[size_t(source)] = MessageReader(message->bytes).get<RankShare>();
                    book.summaryFrom(source);
                    break;
                case MessageTag::Lost:
                    book.lost(source);
                    std::erase(waiting, source);
                    break;
                case MessageTag::Result:
                    book.resultFrom(source);
                    finished(source, message->bytes);
                    waiting.push_back(source);
                    break;
                default:  // Ready
                    waiting.push_back(source);
                    break;
            }
        }
        for (const std::vector<uint8_t>& result : local.takeResults()) {
            busy = true;
            if (result.empty()) return {};  // run() was cancelled: the interruption wins
            finished(0, result);
        }
        if (local.free() && book.itemReady()) {
            local.assign(book.takeItem(0));
            busy = true;
        }
        while (!waiting.empty() && book.itemReady()) {
            channel.send(waiting.front(), MessageTag::Assign,
                         itemMessage(book.takeItem(waiting.front())));
            waiting.pop_front();
            busy = true;
        }
        if (book.allHandedOut()) {
            for (; !waiting.empty(); waiting.pop_front())
                channel.send(waiting.front(), MessageTag::Assign, itemMessage(kNoMoreWork));
        }
        if (!busy) std::this_thread::sleep_for(kPollInterval);
    }
    local.stop();
    shares[0] = local.share();
    shares[0].peakResidentKiB = peakResidentKiB();
    return shares;
}

bool workOnItems(Channel& channel, const WorkItems& items, const std::atomic<bool>* cancel) {
    RankShare share;
    channel.send(0, MessageTag::Ready, {});
    for (;;) {
        auto message = channel.wait(0, MessageTag::Assign, cancel);
        if (!message) return false;
        const auto item = MessageReader(message->bytes).get<int64_t>();
        if (item == kNoMoreWork) break;
        const auto start = std::chrono::steady_clock::now();
        std::vector<uint8_t> result = items.run(item);
        share.busySeconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++share.items;
        if (cancel != nullptr && cancel->load()) return false;
        channel.send(0, MessageTag::Result, result);
    }
    share.peakResidentKiB = peakResidentKiB();
    channel.send(0, MessageTag::Summary, MessageWriter().put(share).bytes());
    return true;
}

}  // namespace quaternia
