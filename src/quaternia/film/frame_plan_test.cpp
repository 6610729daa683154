#include "quaternia/film/frame_plan.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "quaternia/film/film_test_support.h"
#include "quaternia/scene/animation.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/scene/test_scenes.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;
using film_test::namesIn;

// A fresh directory for one test, removed after it.
struct ScratchDirectory : film_test::ScratchDirectory {
    ScratchDirectory() : film_test::ScratchDirectory("frame_plan") {}
};

void touch(const fs::path& path) {
    std::ofstream(path) << "x";
}

TEST(FramePlan, FrameNamesHaveSixDigitsOrAsManyAsTheFilmNeeds) {
    EXPECT_EQ(frameFileName(42, 100), "frame_000042.png");
    EXPECT_EQ(frameFileName(1, 999999), "frame_000001.png");
    EXPECT_EQ(frameFileName(42, 12345678), "frame_00000042.png");
    EXPECT_EQ((FrameDirectory{"out", 10}.framePath(7)), "out/frame_000007.png");
}

TEST(FramePlan, RangeIsTheWholeFilmOrTheFramesGiven) {
    EXPECT_EQ(parseFrameRange("", 24), FrameRange(1, 24));
    EXPECT_EQ(parseFrameRange("3-5", 24), FrameRange(3, 5));
    EXPECT_EQ(parseFrameRange("7", 24), FrameRange(7, 7));
    for (const char* bad : {"5-3", "0-2", "20-25", "a-b", "3-", "-3", "1.5"}) {
        try {
            parseFrameRange(bad, 24);
            ADD_FAILURE() << bad << " was accepted";
        } catch (const UserError& e) {
            EXPECT_EQ(e.key(), "--frames") << bad;
            EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
        }
    }
}

// A frame with a file is complete (frames are renamed into place): a run started again skips it,
// unless it overwrites.
TEST(FramePlan, RenderOnlyTheFramesWithoutAFileUnlessOverwriting) {
    ScratchDirectory scratch;
    const FrameDirectory directory{scratch.path().string(), 6};
    touch(directory.framePath(2));
    touch(directory.framePath(5));
    touch(scratch.path() / "frame_000003.png.tmp-AbC123");  // a killed run's: not a frame
    EXPECT_EQ(framesToRender(directory, {1, 6}, false), (std::vector<int64_t>{1, 3, 4, 6}));
    EXPECT_EQ(framesToRender(directory, {2, 4}, false), (std::vector<int64_t>{3, 4}));
    EXPECT_EQ(framesToRender(directory, {2, 4}, true), (std::vector<int64_t>{2, 3, 4}));
}

// Another run may be writing the frames outside the range into the same directory: only the
// range's stale temporaries go, and the frames written stay.
TEST(FramePlan, PreparingRemovesOnlyTheRangesStaleTemporaries) {
    ScratchDirectory scratch;
    const fs::path frames = scratch.path() / "made" / "frames";
    const FrameDirectory directory{frames.string(), 20};
    prepareDirectory(directory, {1, 4});  // made, with its parents
    ASSERT_TRUE(fs::is_directory(frames));
    EXPECT_TRUE(namesIn(frames).empty());  // the probe of writability left nothing
    touch(frames / "frame_000002.png.tmp-AAAAAA");
    touch(frames / "frame_000009.png.tmp-BBBBBB");
    touch(frames / "frame_000003.png");
    touch(frames / "notes.txt");
    prepareDirectory(directory, {1, 4});
    EXPECT_EQ(
        namesIn(frames),
        (std::vector<std::string>{"frame_000003.png", "frame_000009.png.tmp-BBBBBB", "notes.txt"}));
}

TEST(FramePlan, DirectoryThatCannotBeMadeIsAClearError) {
    ScratchDirectory scratch;
    touch(scratch.path() / "file");
    const FrameDirectory directory{(scratch.path() / "file" / "frames").string(), 3};
    try {
        prepareDirectory(directory, {1, 3});
        ADD_FAILURE() << "a directory under a file was made";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), "-o");
        EXPECT_NE(std::string(e.what()).find("cannot create the frame directory '" +
                                             directory.path + "'"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(namesIn(scratch.path()), std::vector<std::string>{"file"});
}

// Each frame's scene is checked before any work: a video needs frames of one size.
TEST(FramePlan, VideoFramesMustHaveOneSize) {
    Scene film = testing::unitBallScene(32, 24);
    applyOverride(film, "animation.fps=2");
    applyOverride(film,
                  "animation.keys=[{time = 0, \"render.width\" = 32, interpolation = \"step\"}, "
                  "{time = 1, \"render.width\" = 48, interpolation = \"step\"}]");
    validateAnimation(film);
    const int64_t count = filmFrameCount(film);
    ASSERT_EQ(count, 3);
    EXPECT_NO_THROW(checkFrames(film, {1, count}, false));
    EXPECT_NO_THROW(checkFrames(film, {1, 2}, true));
    try {
        checkFrames(film, {1, count}, true);
        ADD_FAILURE() << "frames of two sizes were accepted for a video";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), "--video");
        EXPECT_EQ(std::string(e.what()),
                  "--video: frame 3 is 48x24, frame 1 32x24: a video's frames have one size");
    }
}

// The budget counts the largest frame of the range, once per frame in flight, and for a video
// that frame again as the encoder's RGBA.
TEST(FramePlan, FilmMemoryIsTheLargestFramesTimesTheFramesInFlight) {
    Scene film = testing::unitBallScene(32, 24);
    applyOverride(film, "animation.fps=2");
    applyOverride(film,
                  "animation.keys=[{time = 0, \"render.width\" = 32, interpolation = \"step\"}, "
                  "{time = 1, \"render.width\" = 480, interpolation = \"step\"}]");
    const FilmMemory one = filmMemory(film, {1, 3}, false, 1);
    EXPECT_EQ(one.largestFrame.render.width, 480);
    EXPECT_EQ(filmMemory(film, {1, 3}, false, 3).bytes, 3 * one.bytes);
    EXPECT_GT(filmMemory(film, {1, 3}, true, 1).bytes, one.bytes);
    EXPECT_LT(filmMemory(film, {1, 2}, false, 1).bytes, one.bytes);  // only 32 wide
}

}  // namespace
}  // namespace quaternia
