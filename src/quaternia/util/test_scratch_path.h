// Paths for tests' scratch files that two test processes never share: the same test may run
// twice at once (a local ctest beside a CI run on one machine, or two suites' tests of the same
// name under ctest -j), and a fixed name let one remove the other's files.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace quaternia::testing {

// The temporary directory's `name` with this process's id before its extension ("sky.hdr" ->
// "sky_1234.hdr"), which the readers and writers go by.
inline std::filesystem::path scratchPath(const std::string& name) {
    const std::filesystem::path path(name);
    return std::filesystem::temp_directory_path() /
           (path.stem().string() + "_" + std::to_string(::getpid()) + path.extension().string());
}

}  // namespace quaternia::testing
