// The run-time half of Highway's dynamic dispatch for the quaternia executable.
//
// HWY_DYNAMIC_DISPATCH (camera_lanes.cpp and the other lanes) calls two functions at run
// time, hwy::SupportedTargets and hwy::GetChosenTarget, which Debian's shared libhwy provides.
// Loading that library also runs its static initialisers, among them a timer calibration
// (hwy::platform::TimerResolution) that takes milliseconds: every command paid that before it
// started. So quaternia defines the two here and links with
// --as-needed, which leaves libhwy out of it (CMakeLists.txt); the tests, the benchmarks and
// quaternia-explore, which use more of Highway's run time, link the library.
//
// A target is reported where the CPU has every feature Highway asks of it, or more: SSSE3;
// SSE4 = SSE4.1 and 4.2 with CLMUL and AES; AVX2 = x86-64-v3 (AVX2, BMI1/2, F16C, FMA, LZCNT,
// MOVBE) on top of SSE4; AVX3 = x86-64-v4 (AVX-512 F, CD, BW, DQ, VL) on top of AVX2. GCC's
// __builtin_cpu_supports also checks that the OS saves the AVX and AVX-512 registers.
//
// `quaternia --isa NAME` caps the answer (limitLaneTargets): Highway's better targets have the
// lower bits, so the cap keeps the bits from NAME's up.
#include "cmd/highway_runtime.h"

#include <hwy/targets.h>

#include <cstdint>

namespace {

int64_t gTargetCap = ~int64_t(0);  // the targets limitLaneTargets allows

struct NamedTarget {
    const char* name;
    int64_t target;  // 0: no cap
};

const NamedTarget kNamedTargets[] = {
    {"best", 0},
#if HWY_ARCH_X86
    {"avx3", HWY_AVX3},
    {"avx2", HWY_AVX2},
    {"sse4", HWY_SSE4},
    {"ssse3", HWY_SSSE3},
#endif
    {"scalar", HWY_SCALAR},
};

int64_t cpuTargets() {
#if HWY_ARCH_X86
    __builtin_cpu_init();
    int64_t targets = HWY_SCALAR;
    if (!__builtin_cpu_supports("ssse3")) return targets;
    targets |= HWY_SSSE3;
    if (!(__builtin_cpu_supports("x86-64-v2") && __builtin_cpu_supports("pclmul") &&
          __builtin_cpu_supports("aes"))) {
        return targets;
    }
    targets |= HWY_SSE4;
    if (!__builtin_cpu_supports("x86-64-v3")) return targets;
    targets |= HWY_AVX2;
    if (!__builtin_cpu_supports("x86-64-v4")) return targets;
    return targets | HWY_AVX3;
#else
    return HWY_STATIC_TARGET;
#endif
}

}  // namespace

namespace quaternia {

const std::vector<std::string>& laneTargetNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all;
        for (const NamedTarget& t : kNamedTargets)
            all.push_back(t.name);
        return all;
    }();
    return names;
}

void limitLaneTargets(const std::string& name) {
    for (const NamedTarget& t : kNamedTargets) {
        if (name == t.name) gTargetCap = t.target == 0 ? ~int64_t(0) : ~(t.target - 1);
    }
}

}  // namespace quaternia

namespace hwy {

int64_t SupportedTargets() {
    // The target the code was compiled for outright stays, whatever the cap: the dispatch
    // falls back to it.
    const int64_t cpu = cpuTargets();
    return (cpu & gTargetCap) | (cpu & HWY_STATIC_TARGET);
}

ChosenTarget& GetChosenTarget() {
    static ChosenTarget chosen;
    return chosen;
}

}  // namespace hwy
