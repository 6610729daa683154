// What the film layer's tests share: a fresh directory per test, and the names of the files in
// a directory (outputs are written whole: a test checks that nothing else is left there).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "quaternia/util/test_scratch_path.h"

namespace quaternia::film_test {

// A fresh directory for one test (named after the test and the process), removed after it.
class ScratchDirectory {
  public:
    explicit ScratchDirectory(const std::string& prefix) {
        path_ = quaternia::testing::scratchPath(
            "quaternia_" + prefix + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDirectory() { std::filesystem::remove_all(path_); }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

// The names of the entries of `directory`, sorted.
inline std::vector<std::string> namesIn(const std::filesystem::path& directory) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(directory))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace quaternia::film_test
