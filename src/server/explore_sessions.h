// How the explorer keeps many tabs responsive on few cores: one render slot per client (a new
// request cancels that client's stale render, so the page never waits for a view it has left),
// a bounded number of renders at once, and a per-address token bucket against floods.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace quaternia {

// The cancel flag of one request. Set when a newer request of the same client arrives (or the
// server stops); the render reads it between tiles.
using CancelFlag = std::shared_ptr<std::atomic<bool>>;

class RenderSlots {
  public:
    // A fresh flag for `client`, cancelling the flag its previous request holds. An empty
    // client id shares no slot: its flag is never cancelled by others.
    CancelFlag begin(const std::string& client);
    // Forgets the slot if `flag` is still its current one (the render finished).
    void end(const std::string& client, const CancelFlag& flag);
    // Cancels every render (server shutdown).
    void cancelAll();
    std::size_t activeClients() const;

  private:
    mutable std::mutex mutex_;
    std::map<std::string, CancelFlag> current_;
};

// At most `capacity` renders run at once; the others wait, and give up as soon as they are
// cancelled, so a queue of stale views drains at once.
class RenderGate {
  public:
    explicit RenderGate(int capacity) : capacity_(capacity < 1 ? 1 : capacity) {}

    // Waits for a place; false (no place taken) if `cancel` was set first.
    bool enter(const std::atomic<bool>& cancel);
    void leave();
    // Places taken now.
    int running();

    // Holds a place for its lifetime once entered.
    class Pass {
      public:
        Pass(RenderGate& gate, const std::atomic<bool>& cancel)
            : gate_(gate), entered_(gate.enter(cancel)) {}
        ~Pass() {
            if (entered_) gate_.leave();
        }
        Pass(const Pass&) = delete;
        Pass& operator=(const Pass&) = delete;
        bool entered() const { return entered_; }

      private:
        RenderGate& gate_;
        bool entered_;
    };

  private:
    std::mutex mutex_;
    std::condition_variable freed_;
    int capacity_, running_ = 0;
};

// Token buckets per remote address: `burst` requests at once, refilled at `perSecond`.
class RateLimiter {
  public:
    RateLimiter(double perSecond, double burst) : perSecond_(perSecond), burst_(burst) {}
    // Takes a token for `address`; false when its bucket is empty (answer 429).
    bool allow(const std::string& address);

  private:
    using Clock = std::chrono::steady_clock;
    struct Bucket {
        double tokens;
        Clock::time_point last;
    };
    std::mutex mutex_;
    std::map<std::string, Bucket> buckets_;
    double perSecond_, burst_;
};

}  // namespace quaternia
