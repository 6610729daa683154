// How much memory a request may use, decided before the work starts: a command estimates what its
// buffers need (image and sample buffers, a mesh's blocks and triangles, an animation's frames)
// and refuses, with one line naming the key that sets the size, what does not fit. Without the
// check a large request ends in std::bad_alloc after minutes, or in the kernel's OOM killer.
#pragma once

#include <cstdint>
#include <string>

namespace quaternia {

struct MemoryBudget {
    uint64_t bytes = 0;  // 0: unlimited (nothing is checked)
    std::string source;  // what set it, for the error: "--memory-budget", "available memory", ...
};

// The memory this process can still take, the least of: the address-space limit (RLIMIT_AS,
// `ulimit -v`, less what is mapped now and the reservations `threads` more threads make), the
// data-segment limit (RLIMIT_DATA), the cgroup's memory.max less its use, and the system's
// MemAvailable. Never throws; an unknown quantity does not limit.
MemoryBudget availableMemory(int threads);

// "512M", "8G", "1.5GiB", "4096" (bytes), "auto" (availableMemory), "unlimited" (0). Units are
// powers of 1024. Throws UserError(option, ...) for anything else.
MemoryBudget parseMemoryBudget(const std::string& text, const std::string& option, int threads);

// "1.50 GiB", "12.0 MiB", "512 bytes".
std::string formatBytes(uint64_t bytes);

// Throws MemoryLimitError(key, "<what> needs about N of memory, more than the M available
// (<source>); <advice>") when `needed` exceeds the budget (never when the budget is unlimited).
void requireMemory(uint64_t needed, const MemoryBudget& budget, const std::string& key,
                   const std::string& what, const std::string& advice);

}  // namespace quaternia
