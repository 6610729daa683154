// Running the quaternia binary from a test: a temporary directory per test, the command's exit
// code, standard output and standard error, and the checks every bad-input test makes.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "quaternia/util/test_scratch_path.h"

namespace quaternia::testing {

namespace fs = std::filesystem;

struct CommandResult {
    int exitCode;
    std::string out, err;
};

inline std::string readFile(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

class CliFixture : public ::testing::Test {
  protected:
    void SetUp() override {
        const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = scratchPath("quaternia_cli_" + std::string(test->test_suite_name()) + "_" +
                           test->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    CommandResult run(const std::string& arguments) {
        std::string command = std::string(QUATERNIA_BINARY) + " " + arguments + " >" +
                              (dir_ / "stdout").string() + " 2>" + (dir_ / "stderr").string() +
                              " </dev/null";
        int status = std::system(command.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(dir_ / "stdout"),
                readFile(dir_ / "stderr")};
    }
    fs::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name) << text;
        return dir_ / name;
    }
    std::string output(const std::string& name = "out.png") const { return (dir_ / name).string(); }
    // Nothing but the files the test made itself: no output, no temporary left behind.
    void expectNoOutput() const {
        for (const auto& entry : fs::directory_iterator(dir_)) {
            std::string name = entry.path().filename().string();
            EXPECT_TRUE(name == "stdout" || name == "stderr" || name.ends_with(".toml"))
                << "left behind: " << name;
        }
    }
    // One line on stderr, exit code 2, mentioning `needle`.
    void expectUserError(const CommandResult& r, const std::string& needle) {
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_NE(r.err.find(needle), std::string::npos) << "stderr: " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        expectNoOutput();
    }

    fs::path dir_;
};

}  // namespace quaternia::testing
