#include "quaternia/film/frame_writer.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "quaternia/film/film_test_support.h"
#include "quaternia/render/render_png.h"
#include "quaternia/scene/test_scenes.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;
using film_test::namesIn;

// A fresh directory for one test, removed after it.
struct ScratchDirectory : film_test::ScratchDirectory {
    ScratchDirectory() : film_test::ScratchDirectory("frame_writer") {}
};

std::vector<uint8_t> fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

RenderResult renderedFrame(int width, int height) {
    RenderOptions options;
    options.threads = 2;
    return renderForPng(testing::unitBallScene(width, height), options);
}

TEST(FrameWriter, HandlesEveryFrameInTheOrderHandedOver) {
    std::vector<int64_t> handled;
    FrameWriter writer([&](FrameWork& work) { handled.push_back(work.frame); }, 1);
    for (int64_t frame : {4, 5, 6, 7, 8})
        writer.push({frame, std::nullopt, 8});
    writer.finish();
    EXPECT_EQ(handled, (std::vector<int64_t>{4, 5, 6, 7, 8}));
}

// The first error ends the writing: the frames after it are not handled, and the error comes
// back to the renderer's thread.
TEST(FrameWriter, RethrowsTheFirstErrorAndHandlesNothingAfterIt) {
    std::mutex mutex;
    std::vector<int64_t> handled;
    FrameWriter writer(
        [&](FrameWork& work) {
            std::lock_guard lock(mutex);
            handled.push_back(work.frame);
            if (work.frame == 2) throw std::runtime_error("disk on fire");
        },
        1);
    try {
        for (int64_t frame = 1; frame <= 5; ++frame)
            writer.push({frame, std::nullopt, 8});
        writer.finish();
        ADD_FAILURE() << "the handler's error was lost";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "disk on fire");
    }
    std::lock_guard lock(mutex);
    EXPECT_EQ(handled, (std::vector<int64_t>{1, 2}));
}

// A rendered frame becomes its PNG, under the film's name for it, and nothing else is left in
// the directory (no temporary).
TEST(FrameFiles, EachRenderedFrameIsItsPngUnderItsName) {
    ScratchDirectory scratch;
    const FrameDirectory directory{scratch.path().string(), 1200000};
    RenderResult first = renderedFrame(40, 30), second = renderedFrame(24, 16);
    const std::vector<uint8_t> firstPng = encodeRenderPng(first, 8),
                               secondPng = encodeRenderPng(second, 8);
    FrameWriter writer(frameFileHandler(directory, nullptr), 1);
    writer.push({3, std::move(first), 8});
    writer.push({1000000, std::move(second), 8});
    writer.push({4, std::nullopt, 8});  // not rendered, and no encoder: nothing to do
    writer.finish();
    EXPECT_EQ(namesIn(scratch.path()),
              (std::vector<std::string>{"frame_0000003.png", "frame_1000000.png"}));
    EXPECT_EQ(fileBytes(scratch.path() / "frame_0000003.png"), firstPng);
    EXPECT_EQ(fileBytes(scratch.path() / "frame_1000000.png"), secondPng);
}

TEST(FrameFiles, UnwritableDirectoryIsAClearErrorAndLeavesNoFile) {
    ScratchDirectory scratch;
    std::ofstream(scratch.path() / "file") << "not a directory";
    const FrameDirectory directory{(scratch.path() / "file").string(), 10};
    FrameWriter writer(frameFileHandler(directory, nullptr), 1);
    try {
        writer.push({1, renderedFrame(16, 16), 8});
        writer.finish();
        ADD_FAILURE() << "a frame was written under a file";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cannot write '" + directory.framePath(1) + "': Not a directory");
    }
    EXPECT_EQ(namesIn(scratch.path()), std::vector<std::string>{"file"});
}

// A frame whose write fails half-way (here the file size limit, as a full disk would) leaves
// neither a truncated frame nor its temporary: a run started again renders it whole.
TEST(FrameFiles, WriteFailingHalfWayLeavesNoHalfFrame) {
    ScratchDirectory scratch;
    const FrameDirectory directory{scratch.path().string(), 10};
    RenderResult frame = renderedFrame(64, 48);
    ASSERT_GT(encodeRenderPng(frame, 8).size(), 1024u);
    rlimit limit{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &limit), 0);
    const rlimit saved = limit;
    limit.rlim_cur = 512;                            // bytes: the frame's PNG is larger
    auto* previous = std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limit), 0);
    std::string error;
    {
        FrameWriter writer(frameFileHandler(directory, nullptr), 1);
        try {
            writer.push({7, std::move(frame), 8});
            writer.finish();
        } catch (const UserError& e) {
            error = e.what();
        }
    }
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previous);
    EXPECT_EQ(error, "cannot write '" + directory.framePath(7) + "': File too large");
    EXPECT_TRUE(namesIn(scratch.path()).empty());
}

}  // namespace
}  // namespace quaternia
