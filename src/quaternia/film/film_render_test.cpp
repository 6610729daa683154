#include "quaternia/film/film_render.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "quaternia/film/film_test_support.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/render_png.h"
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
    ScratchDirectory() : film_test::ScratchDirectory("film") {}
};

std::vector<uint8_t> fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

// Four small frames of the unit ball turning in its slice.
Scene smallFilm() {
    Scene film = testing::unitBallScene(32, 24);
    applyOverride(film, "animation.turns=1");
    applyOverride(film, "animation.frames=4");
    applyOverride(film, "animation.orbit_turns=1");
    validateAnimation(film);
    return film;
}

// Frame n's file is the PNG render of the film's scene at frame n.
std::vector<uint8_t> expectedFrame(const Scene& film, int64_t frame) {
    RenderOptions options;
    options.threads = 2;
    return renderPng(sceneAtFrame(film, frame), options).png;
}

// Resuming: the frames with a file are skipped (and read back for the video), the others
// rendered and written; every file is the render of its frame's scene.
TEST(FilmRender, RendersTheMissingFramesAndEncodesTheWholeRange) {
    ScratchDirectory scratch;
    const Scene film = smallFilm();
    const FrameDirectory directory{scratch.path().string(), filmFrameCount(film)};
    RenderOptions one;
    one.threads = 2;
    ASSERT_TRUE(renderFrameFile(film, directory, 2, one));  // as another process would
    std::optional<VideoEncoder> encoder;
    const fs::path video = scratch.path() / "film.gif";
    std::string ffmpeg;
    try {
        ffmpeg = findFfmpeg();
        encoder.emplace(ffmpeg, AtomicFile(video.string()), VideoFormat::Gif, 32, 24, 10);
    } catch (const UserError&) {
        // no ffmpeg: the frames alone
    }
    WorkOptions options;
    options.threads = 2;
    std::vector<double> progress;
    options.progress = [&](double fraction) { progress.push_back(fraction); };
    const FilmRun run = renderFilmFrames(film, directory, {1, 4}, {1, 3, 4},
                                         encoder ? &*encoder : nullptr, options);
    EXPECT_FALSE(run.interrupted);
    EXPECT_EQ(run.stats.rendered, 3);
    EXPECT_EQ(run.stats.skipped, 1);
    EXPECT_GT(run.stats.renderSeconds, 0);
    for (int64_t frame = 1; frame <= 4; ++frame)
        EXPECT_EQ(fileBytes(directory.framePath(frame)), expectedFrame(film, frame)) << frame;
    ASSERT_FALSE(progress.empty());
    EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
    EXPECT_LE(progress.back(), 1.0);
    EXPECT_GE(progress.back(), 2.0 / 3);  // the last of the three frames
    if (encoder) {
        encoder->finish();
        EXPECT_GT(fs::file_size(video), 0u);
    }
}

// Frames written by many processes become one video in order.
TEST(FilmRender, FrameFilesEncodeInOrder) {
    ScratchDirectory scratch;
    std::string ffmpeg;
    try {
        ffmpeg = findFfmpeg();
    } catch (const UserError&) {
        GTEST_SKIP() << "no ffmpeg on PATH";
    }
    const Scene film = smallFilm();
    const FrameDirectory directory{scratch.path().string(), filmFrameCount(film)};
    RenderOptions one;
    one.threads = 2;
    for (int64_t frame : {3, 1, 2})
        ASSERT_TRUE(renderFrameFile(film, directory, frame, one));
    const fs::path video = scratch.path() / "film.gif";
    VideoEncoder encoder(ffmpeg, AtomicFile(video.string()), VideoFormat::Gif, 32, 24, 10);
    encodeFrameFiles(encoder, directory, {1, 3});
    encoder.finish();
    EXPECT_GT(fs::file_size(video), 0u);
    // A missing frame file is the error of reading it.
    VideoEncoder again(ffmpeg, AtomicFile(video.string()), VideoFormat::Gif, 32, 24, 10);
    EXPECT_THROW(encodeFrameFiles(again, directory, {1, 4}), UserError);
}

// Cancelled before the first frame: nothing is rendered and nothing written.
TEST(FilmRender, CancelledRunWritesNothingAndSaysSo) {
    ScratchDirectory scratch;
    const Scene film = smallFilm();
    const FrameDirectory directory{scratch.path().string(), filmFrameCount(film)};
    std::atomic<bool> cancel{true};
    WorkOptions options;
    options.threads = 2;
    options.cancel = &cancel;
    const FilmRun run = renderFilmFrames(film, directory, {1, 4}, {1, 2, 3, 4}, nullptr, options);
    EXPECT_TRUE(run.interrupted);
    EXPECT_EQ(run.stats.rendered, 0);
    EXPECT_TRUE(fs::is_empty(scratch.path()));
    RenderOptions one;
    one.cancel = &cancel;
    EXPECT_FALSE(renderFrameFile(film, directory, 1, one));
    EXPECT_TRUE(fs::is_empty(scratch.path()));
}

}  // namespace
}  // namespace quaternia
