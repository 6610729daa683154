#include "quaternia/distribute/local_worker.h"

#include <chrono>
#include <iterator>
#include <utility>

namespace quaternia {

LocalWorker::LocalWorker(const WorkItems& items) : items_(items), thread_([this] { loop(); }) {}

LocalWorker::~LocalWorker() {
    stop();
    thread_.join();
}

bool LocalWorker::free() {
    std::lock_guard lock(mutex_);
    return !assigned_ && !running_ && !stopped_;
}

void LocalWorker::assign(int64_t item) {
    std::lock_guard lock(mutex_);
    assigned_ = item;
    changed_.notify_all();
}

void LocalWorker::stop() {
    std::lock_guard lock(mutex_);
    stopped_ = true;
    changed_.notify_all();
}

std::vector<std::vector<uint8_t>> LocalWorker::takeResults() {
    std::lock_guard lock(mutex_);
    if (error_) std::rethrow_exception(error_);
    std::vector<std::vector<uint8_t>> out(std::make_move_iterator(results_.begin()),
                                          std::make_move_iterator(results_.end()));
    results_.clear();
    return out;
}

RankShare LocalWorker::share() {
    std::lock_guard lock(mutex_);
    return share_;
}

void LocalWorker::loop() {
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
        share_.busySeconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++share_.items;
        if (error) {
            error_ = error;
            return;
        }
        results_.push_back(std::move(result));
    }
}

}  // namespace quaternia
