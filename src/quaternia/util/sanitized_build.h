// Whether the tests run in the AddressSanitizer + UndefinedBehaviorSanitizer build
// (QUATERNIA_SANITIZE, which defines QUATERNIA_SANITIZED_BUILD for the tests). The heaviest
// accuracy tests then check some of their cases, not all: their arithmetic is the Release
// build's, which checks every case; under the sanitizers the point is the memory and undefined
// behaviour checks of each path, which those cases take. It keeps the test command within its
// time on 2 cores.
#pragma once

namespace quaternia::testing {

#ifdef QUATERNIA_SANITIZED_BUILD
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

// Whether case `index` of a heavy test runs: every one in Release, every `stride`-th under the
// sanitizers.
inline bool runsCase(int index, int stride) {
    return !kSanitizedBuild || index % stride == 0;
}

}  // namespace quaternia::testing
