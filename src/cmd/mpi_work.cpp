#include "cmd/mpi_work.h"

#include <sys/resource.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace quaternia {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Rank 0's own worker: a thread that runs one item at a time as the main thread assigns them
// (the main thread alone calls MPI), and keeps the results for it.
class LocalWorker {
  public:
    explicit LocalWorker(const WorkItems& items) : items_(items), thread_([this] { loop(); }) {}
    ~LocalWorker() {
        stop();
        thread_.join();
    }
    // Free for an item: none assigned or running, and not stopped.
    bool free() {
        std::lock_guard lock(mutex_);
        return !assigned_ && !running_ && !stopped_;
    }
    void assign(int64_t item) {
        std::lock_guard lock(mutex_);
        assigned_ = item;
        changed_.notify_all();
    }
    void stop() {
        std::lock_guard lock(mutex_);
        stopped_ = true;
        changed_.notify_all();
    }
    // The results finished since the last call; rethrows the thread's error.
    std::vector<std::vector<uint8_t>> takeResults() {
        std::lock_guard lock(mutex_);
        if (error_) std::rethrow_exception(error_);
        std::vector<std::vector<uint8_t>> out(std::make_move_iterator(results_.begin()),
                                              std::make_move_iterator(results_.end()));
        results_.clear();
        return out;
    }
    RankShare share() {
        std::lock_guard lock(mutex_);
        return share_;
    }

  private:
    void loop() {
        for (;;) {
            int64_t item;
            {
                std::unique_lock lock(mutex_);
                changed_.wait(lock, [&] { return assigned_.has_value() || stopped_; });
                if (!assigned_) return;
                item = *assigned_;
                assigned_.reset();
                running_ = true;
            }
            const auto start = std::chrono::steady_clock::now();
            std::vector<uint8_t> result;
            std::exception_ptr error;
            try {
                result = items_.run(item);
            } catch (...) {
                error = std::current_exception();
            }
            std::lock_guard lock(mutex_);
            running_ = false;
            share_.busySeconds += secondsSince(start);
            ++share_.items;
            if (error) {
                error_ = error;
                return;
            }
            results_.push_back(std::move(result));
        }
    }

    const WorkItems& items_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<int64_t> assigned_;
    bool running_ = false, stopped_ = false;
    std::deque<std::vector<uint8_t>> results_;
    std::exception_ptr error_;
    RankShare share_;
    std::thread thread_;
};

std::vector<uint8_t> itemMessage(int64_t item) {
    return MessageWriter().put(item).bytes();
}

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

void printRankShares(const std::vector<RankShare>& shares, const char* itemsName) {
    for (size_t rank = 0; rank < shares.size(); ++rank)
        std::printf("  rank %zu: %lld %s, %.2f s rendering, peak %.0f MiB resident\n", rank,
                    (long long)shares[rank].items, itemsName, shares[rank].busySeconds,
                    double(shares[rank].peakResidentKiB) / 1024);
}

std::function<void(int64_t, int64_t)> progressOn(ProgressBar& bar, const char* itemsName) {
    return [&bar, itemsName](int64_t done, int64_t count) {
        bar.update(double(done) / double(std::max<int64_t>(1, count)),
                   std::to_string(done) + "/" + std::to_string(count) + " " + itemsName);
    };
}

int64_t peakResidentKiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return int64_t(usage.ru_maxrss);  // KiB on Linux
}

std::vector<RankShare> handOutWork(const MpiSession& mpi, const WorkItems& items,
                                   const std::atomic<bool>* cancel) {
    std::vector<RankShare> shares(size_t(mpi.size()));
    LocalWorker local(items);
    std::deque<int> waiting;  // ranks free for work, first come first served
    int64_t next = 0, done = 0;
    int summaries = 0;
    const int workers = mpi.size() - 1;
    auto finished = [&](int source, const std::vector<uint8_t>& result) {
        items.take(source, result);
        ++done;
        if (items.progress) items.progress(done, items.count);
    };
    while (done < items.count || summaries < workers) {
        if (cancel != nullptr && cancel->load()) return {};
        bool busy = false;
        while (auto message = pollMessage(cancel)) {
            busy = true;
            if (message->tag == MessageTag::Summary) {
                MessageReader reader(message->bytes);
                shares[size_t(message->source)] = reader.get<RankShare>();
                ++summaries;
                continue;
            }
            if (message->tag == MessageTag::Result) finished(message->source, message->bytes);
            waiting.push_back(message->source);
        }
        for (const std::vector<uint8_t>& result : local.takeResults()) {
            busy = true;
            if (result.empty()) return {};  // run() was cancelled: the interruption wins
            finished(0, result);
        }
        if (local.free() && next < items.count && items.mayStart(next)) {
            local.assign(next++);
            busy = true;
        }
        while (!waiting.empty() && next < items.count && items.mayStart(next)) {
            sendMessage(waiting.front(), MessageTag::Assign, itemMessage(next++));
            waiting.pop_front();
            busy = true;
        }
        if (next == items.count) {
            for (; !waiting.empty(); waiting.pop_front())
                sendMessage(waiting.front(), MessageTag::Assign, itemMessage(kNoMoreWork));
        }
        if (!busy) std::this_thread::sleep_for(kPollInterval);
    }
    local.stop();
    shares[0] = local.share();
    shares[0].peakResidentKiB = peakResidentKiB();
    return shares;
}

bool workOnItems(const WorkItems& items, const std::atomic<bool>* cancel) {
    RankShare share;
    sendMessage(0, MessageTag::Ready, {});
    for (;;) {
        auto message = waitMessage(0, MessageTag::Assign, cancel);
        if (!message) return false;
        const auto item = MessageReader(message->bytes).get<int64_t>();
        if (item == kNoMoreWork) break;
        const auto start = std::chrono::steady_clock::now();
        std::vector<uint8_t> result = items.run(item);
        share.busySeconds += secondsSince(start);
        ++share.items;
        if (cancel != nullptr && cancel->load()) return false;
        sendMessage(0, MessageTag::Result, result);
    }
    share.peakResidentKiB = peakResidentKiB();
    sendMessage(0, MessageTag::Summary, MessageWriter().put(share).bytes());
    return true;
}

}  // namespace quaternia
