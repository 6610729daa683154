// The few MPI calls quaternia-mpi makes, in one place: the session, binary messages of bytes,
// and waiting for a message without spinning. OpenMPI's blocking receive polls on a core while
// it waits; here a rank sleeps between probes (kPollInterval), so that a rank waiting for work
// or for a result leaves the core to the renders beside it.
//
// Messages carry plain structs as bytes (MessageWriter, MessageReader): the ranks of one job run
// the same binary on machines of one architecture, as MPI jobs do.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace quaternia {

inline constexpr std::chrono::microseconds kPollInterval{200};

// The messages of quaternia-mpi, by tag.
enum class MessageTag : int {
    Ready = 1,  // worker -> 0: free for work (the first time; a result says it after that)
    Result,     // worker -> 0: a unit or frame done, and free for the next
    Assign,     // 0 -> worker: the next unit or frame, or kNoMoreWork
    Summary,    // worker -> 0: what it did, after kNoMoreWork
};
inline constexpr int64_t kNoMoreWork = -1;

// MPI_Init_thread (funnelled: only the main thread calls MPI) and MPI_Finalize.
class MpiSession {
  public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    int rank() const { return rank_; }
    int size() const { return size_; }
    // Every rank's `status` agreed: the largest (collective: every rank calls it).
    int agree(int status) const;
    // Ends the whole job now (MPI_Abort) with `code`.
    [[noreturn]] void abort(int code) const;

  private:
    int rank_ = 0, size_ = 1;
};

struct Message {
    int source = 0;
    MessageTag tag = MessageTag::Ready;
    std::vector<uint8_t> bytes;
};

void sendMessage(int destination, MessageTag tag, const std::vector<uint8_t>& bytes);
// The next message from any rank with any tag if one has arrived, else nothing; nothing too if
// `cancel` is set while its bytes are still coming (their sender may have died).
std::optional<Message> pollMessage(const std::atomic<bool>* cancel);
// Waits (sleeping between probes) for a message from `source` with `tag`; nothing if `cancel`
// is set first.
std::optional<Message> waitMessage(int source, MessageTag tag, const std::atomic<bool>* cancel);

// Plain values appended as bytes, and read back in the same order.
class MessageWriter {
  public:
    template <class T>
    MessageWriter& put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        const size_t at = bytes_.size();
        bytes_.resize(at + sizeof(T));
        std::memcpy(bytes_.data() + at, &value, sizeof(T));
        return *this;
    }
    MessageWriter& putBytes(const std::vector<uint8_t>& bytes) {
        put(uint64_t(bytes.size()));
        bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
        return *this;
    }
    const std::vector<uint8_t>& bytes() const { return bytes_; }

  private:
    std::vector<uint8_t> bytes_;
};

class MessageReader {
  public:
    explicit MessageReader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        need(sizeof(T));
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return value;
    }
    std::vector<uint8_t> getBytes() {
        const auto size = get<uint64_t>();
        need(size);
        std::vector<uint8_t> out(bytes_.begin() + std::ptrdiff_t(at_),
                                 bytes_.begin() + std::ptrdiff_t(at_ + size));
        at_ += size;
        return out;
    }

  private:
    void need(size_t size) const {
        if (size > bytes_.size() - at_) throw std::runtime_error("truncated MPI message");
    }
    const std::vector<uint8_t>& bytes_;
    size_t at_ = 0;
};

}  // namespace quaternia
