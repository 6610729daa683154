#include "quaternia/util/memory_budget.h"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "quaternia/util/error.h"

namespace quaternia {
namespace {

constexpr uint64_t kUnknown = std::numeric_limits<uint64_t>::max();
constexpr uint64_t kMiB = uint64_t(1) << 20;
// Address space each further thread reserves under RLIMIT_AS: its stack (glibc's default,
// RLIMIT_STACK's 8 MiB) and the 64 MiB heap arena glibc's malloc maps per thread on 64 bits.
constexpr uint64_t kThreadReservation = 72 * kMiB;
// What the process maps beyond the estimated buffers: code, libraries, small allocations.
constexpr uint64_t kBaseReservation = 64 * kMiB;

// A field "Name:   123 kB" of /proc/self/status or /proc/meminfo, in bytes.
uint64_t procField(const char* path, const char* name) {
    std::ifstream in(path);
    std::string line;
    const size_t length = std::strlen(name);
    while (std::getline(in, line)) {
        if (line.compare(0, length, name) != 0 || line.size() <= length || line[length] != ':')
            continue;
        uint64_t value = 0;
        std::istringstream fields(line.substr(length + 1));
        std::string unit;
        if (!(fields >> value)) return kUnknown;
        fields >> unit;
        return unit == "kB" ? value * 1024 : value;
    }
    return kUnknown;
}

uint64_t softLimit(int resource) {
    struct rlimit limit;
    if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnknown;
    return uint64_t(limit.rlim_cur);
}

uint64_t room(uint64_t limit, uint64_t used, uint64_t reserved) {
    if (limit == kUnknown) return kUnknown;
    if (used == kUnknown) used = 0;
    return limit > used + reserved ? limit - used - reserved : 0;
}

uint64_t readNumber(const std::string& path) {
    std::ifstream in(path);
    uint64_t value;
    if (in >> value) return value;
    return kUnknown;  // "max", or no such file
}

// cgroup v2: the group's path is the "0::" line of /proc/self/cgroup.
uint64_t cgroupRoom() {
    std::ifstream in("/proc/self/cgroup");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("0::", 0) != 0) continue;
        const std::string group = "/sys/fs/cgroup" + line.substr(3);
        return room(readNumber(group + "/memory.max"), readNumber(group + "/memory.current"), 0);
    }
    return kUnknown;
}

}  // namespace

MemoryBudget availableMemory(int threads) {
    struct Candidate {
        uint64_t bytes;
        const char* source;
    };
    const uint64_t reserved =
        kBaseReservation + uint64_t(std::max(threads, 1)) * kThreadReservation;
    const Candidate candidates[] = {
        {room(softLimit(RLIMIT_AS), procField("/proc/self/status", "VmSize"), reserved),
         "the address-space limit, ulimit -v"},
        {room(softLimit(RLIMIT_DATA), procField("/proc/self/status", "VmData"), reserved),
         "the data-size limit, ulimit -d"},
        {cgroupRoom(), "the cgroup's memory.max"},
        {procField("/proc/meminfo", "MemAvailable"), "available memory"},
    };
    MemoryBudget budget;
    for (const Candidate& candidate : candidates) {
        if (candidate.bytes == kUnknown) continue;
        if (budget.source.empty() || candidate.bytes < budget.bytes) {
            budget.bytes = std::max<uint64_t>(candidate.bytes, 1);  // 0 would mean unlimited
            budget.source = candidate.source;
        }
    }
    return budget;
}

MemoryBudget parseMemoryBudget(const std::string& text, const std::string& option, int threads) {
    if (text == "auto") return availableMemory(threads);
    if (text == "unlimited") return {0, option};
    const auto bad = [&] {
        return UserError(option, option +
                                     " must be a size such as 512M, 8G or 1.5GiB, or auto "
                                     "or unlimited, got '" +
                                     text + "'");
    };
    size_t end = 0;
    double value;
    try {
        value = std::stod(text, &end);
    } catch (const std::exception&) {
        throw bad();
    }
    std::string unit = text.substr(end);
    if (unit.size() == 3 && unit.substr(1) == "iB") unit = unit.substr(0, 1);
    if (unit.size() == 2 && (unit[1] == 'B' || unit[1] == 'b')) unit = unit.substr(0, 1);
    const std::string units = "KMGT";
    double scale = 1;
    if (!unit.empty()) {
        const size_t power =
            unit.size() == 1 ? units.find(char(std::toupper(unit[0]))) : std::string::npos;
        if (power == std::string::npos) throw bad();
        scale = std::pow(1024.0, double(power + 1));
    }
    const double bytes = value * scale;
    if (!std::isfinite(bytes) || bytes < 1 || bytes > 1e18) throw bad();
    return {uint64_t(bytes), option};
}

std::string formatBytes(uint64_t bytes) {
    const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
    if (bytes < 1024) return std::to_string(bytes) + " bytes";
    double value = double(bytes);
    int unit = -1;
    while (value >= 1024 && unit < 3) {
        value /= 1024;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text,
                  value < 10    ? "%.2f %s"
                  : value < 100 ? "%.1f %s"
                                : "%.0f %s",
                  value, units[unit]);
    return text;
}

void requireMemory(uint64_t needed, const MemoryBudget& budget, const std::string& key,
                   const std::string& what, const std::string& advice) {
    if (budget.bytes == 0 || needed <= budget.bytes) return;
    throw MemoryLimitError(key, what + " needs about " + formatBytes(needed) +
                                    " of memory, more than the " + formatBytes(budget.bytes) +
                                    " available (" + budget.source + "); " + advice);
}

}  // namespace quaternia
