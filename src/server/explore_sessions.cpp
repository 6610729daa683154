#include "server/explore_sessions.h"

#include <algorithm>

namespace quaternia {

CancelFlag RenderSlots::begin(const std::string& client) {
    auto flag = std::make_shared<std::atomic<bool>>(false);
    if (client.empty()) return flag;
    std::lock_guard lock(mutex_);
    CancelFlag& slot = current_[client];
    if (slot) *slot = true;
    slot = flag;
    return flag;
}

void RenderSlots::end(const std::string& client, const CancelFlag& flag) {
    if (client.empty()) return;
    std::lock_guard lock(mutex_);
    auto it = current_.find(client);
    if (it != current_.end() && it->second == flag) current_.erase(it);
}

void RenderSlots::cancelAll() {
    std::lock_guard lock(mutex_);
    for (auto& [client, flag] : current_)
        *flag = true;
}

std::size_t RenderSlots::activeClients() const {
    std::lock_guard lock(mutex_);
    return current_.size();
}

bool RenderGate::enter(const std::atomic<bool>& cancel) {
    std::unique_lock lock(mutex_);
    // Cancellation comes from another thread without notifying this condition variable, so
    // waiting is in short slices that re-read the flag.
    while (running_ >= capacity_) {
        if (cancel) return false;
        freed_.wait_for(lock, std::chrono::milliseconds(5));
    }
    if (cancel) return false;
    ++running_;
    return true;
}

int RenderGate::running() {
    std::lock_guard<std::mutex> lock(mutex_);
    return running_;
}

void RenderGate::leave() {
    {
        std::lock_guard lock(mutex_);
        --running_;
    }
    freed_.notify_one();
}

bool RateLimiter::allow(const std::string& address) {
    std::lock_guard lock(mutex_);
    Clock::time_point now = Clock::now();
    // Bounded memory under a flood from many addresses: buckets idle long enough to be full
    // again are dropped (a full bucket is what a new one starts as).
    if (buckets_.size() > 10000) {
        std::erase_if(buckets_, [&](const auto& entry) {
            double idle = std::chrono::duration<double>(now - entry.second.last).count();
            return entry.second.tokens + idle * perSecond_ >= burst_;
        });
    }
    auto [it, inserted] = buckets_.try_emplace(address, Bucket{burst_, now});
    Bucket& bucket = it->second;
    double elapsed = std::chrono::duration<double>(now - bucket.last).count();
    bucket.tokens = std::min(burst_, bucket.tokens + elapsed * perSecond_);
    bucket.last = now;
    if (bucket.tokens < 1) return false;
    bucket.tokens -= 1;
    return true;
}

}  // namespace quaternia
