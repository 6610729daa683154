#include "cmd/mpi_report.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace quaternia {

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

}  // namespace quaternia
