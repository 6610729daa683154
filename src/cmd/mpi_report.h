// What quaternia-mpi shows of the ranks' work: the progress bar as results come back, and each
// rank's share after the summary.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "cmd/progress_bar.h"
#include "quaternia/distribute/work_scheduler.h"

namespace quaternia {

// Each rank's share as lines on stdout ("  rank 1: 12 frames, 3.20 s rendering, peak 20 MiB
// resident").
void printRankShares(const std::vector<RankShare>& shares, const char* itemsName);

// A progress callback for WorkItems: the bar with "done/count <itemsName>" after the ETA.
std::function<void(int64_t, int64_t)> progressOn(ProgressBar& bar, const char* itemsName);

}  // namespace quaternia
