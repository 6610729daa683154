// quaternia's answer to Highway's run-time dispatch (highway_runtime.cpp), and the cap on it that
// `quaternia --isa` sets: benchmarks of an AVX2 machine's speed run on an AVX-512 one.
#pragma once

#include <string>
#include <vector>

namespace quaternia {

// The names `--isa` accepts, best first: "best" (no cap), then Highway's x86 targets.
const std::vector<std::string>& laneTargetNames();

// Lanes run the best instruction set the CPU supports that is no better than `name` (one of
// laneTargetNames()). Call before the first render: Highway keeps its first choice.
void limitLaneTargets(const std::string& name);

}  // namespace quaternia
