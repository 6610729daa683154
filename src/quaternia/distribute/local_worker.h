// Rank 0's own worker: a thread that runs one item at a time as the scheduler assigns them (the
// scheduler's thread alone talks on the channel, which MPI's funnelled mode requires), and keeps
// the results for it.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "quaternia/distribute/work_scheduler.h"

namespace quaternia {

class LocalWorker {
  public:
    explicit LocalWorker(const WorkItems& items);
    // Stops after the item running, if any (whose run() the cancel flag should end soon).
    ~LocalWorker();
    LocalWorker(const LocalWorker&) = delete;
    LocalWorker& operator=(const LocalWorker&) = delete;

    // Free for an item: none assigned or running, and not stopped.
    bool free();
    void assign(int64_t item);
    void stop();
    // The results finished since the last call, in the order finished; rethrows the thread's
    // error.
    std::vector<std::vector<uint8_t>> takeResults();
    RankShare share();

  private:
    void loop();

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

}  // namespace quaternia
