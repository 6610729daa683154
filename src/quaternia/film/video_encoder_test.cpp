#include "quaternia/film/video_encoder.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "quaternia/film/film_test_support.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;
using film_test::namesIn;

// A fresh directory for one test, removed after it.
struct ScratchDirectory : film_test::ScratchDirectory {
    ScratchDirectory() : film_test::ScratchDirectory("video") {}
};

std::optional<std::string> ffmpegOnPath() {
    try {
        return findFfmpeg();
    } catch (const UserError&) {
        return std::nullopt;
    }
}

// A width x height frame of one colour.
Image solidFrame(int width, int height, Rgba colour) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = colour;
    return image;
}

// What ffprobe reads of the video's first stream, "codec,width,height,frames" (every frame
// decoded to count them), or nullopt where there is no ffprobe.
std::optional<std::string> probe(const fs::path& video) {
    if (std::system("command -v ffprobe > /dev/null 2>&1") != 0) return std::nullopt;
    const std::string command =
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
        "stream=codec_name,width,height,nb_read_frames -of csv=p=0 '" +
        video.string() + "' 2>&1";
    std::FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) return std::nullopt;
    std::string out;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr)
        out += buffer;
    ::pclose(pipe);
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r'))
        out.pop_back();
    return out;
}

std::string headOf(const fs::path& path, size_t bytes) {
    std::ifstream in(path, std::ios::binary);
    std::string head(bytes, '\0');
    in.read(head.data(), std::streamsize(bytes));
    head.resize(size_t(in.gcount()));
    return head;
}

// Encodes `frames` frames of width x height into `video`; throws what the encoder throws.
void encode(const std::string& ffmpeg, const fs::path& video, VideoFormat format, int width,
            int height, double fps, int frames) {
    VideoEncoder encoder(ffmpeg, AtomicFile(video.string()), format, width, height, fps);
    for (int i = 0; i < frames; ++i)
        encoder.addFrame(solidFrame(width, height, Rgba{0.2f * float(i), 0.5f, 1, 1}));
    encoder.finish();
}

TEST(VideoEncoder, FormatIsTheOutputsExtensionInAnyCase) {
    EXPECT_EQ(videoFormatOf("film.mp4"), VideoFormat::Mp4);
    EXPECT_EQ(videoFormatOf("dir.v2/FILM.MP4"), VideoFormat::Mp4);
    EXPECT_EQ(videoFormatOf("film.WebM"), VideoFormat::WebM);
    EXPECT_EQ(videoFormatOf("film.gif"), VideoFormat::Gif);
    for (const char* bad : {"film.avi", "film", "mp4"}) {
        try {
            videoFormatOf(bad);
            ADD_FAILURE() << bad << " was accepted";
        } catch (const UserError& e) {
            EXPECT_EQ(e.key(), "--video");
            EXPECT_NE(std::string(e.what()).find("unknown video format"), std::string::npos);
        }
    }
}

// YUV 4:2:0 needs even sizes: MP4 and WebM pad an odd frame by a black row or column; a GIF
// keeps its size. The frame rate goes exactly.
TEST(VideoEncoder, YuvFormatsPadOddSizesAndGifKeepsThem) {
    auto has = [](const std::vector<std::string>& args, const std::string& arg) {
        return std::find(args.begin(), args.end(), arg) != args.end();
    };
    const std::string pad = "pad=ceil(iw/2)*2:ceil(ih/2)*2";
    for (VideoFormat format : {VideoFormat::Mp4, VideoFormat::WebM}) {
        const auto args = ffmpegArguments(format, 33, 21, 29.97, "out");
        EXPECT_TRUE(has(args, pad));
        EXPECT_TRUE(has(args, "33x21"));
        EXPECT_TRUE(has(args, "29.97"));
        EXPECT_TRUE(has(args, "yuv420p"));
        EXPECT_EQ(args.back(), "out");
    }
    const auto gif = ffmpegArguments(VideoFormat::Gif, 33, 21, 24, "out.gif");
    EXPECT_FALSE(has(gif, pad));
    EXPECT_TRUE(has(gif, "24"));
    EXPECT_TRUE(has(gif, "gif"));
}

TEST(VideoEncoder, ShortMp4IsPlayable) {
    const auto ffmpeg = ffmpegOnPath();
    if (!ffmpeg) GTEST_SKIP() << "no ffmpeg on PATH";
    ScratchDirectory scratch;
    const fs::path video = scratch.path() / "film.mp4";
    encode(*ffmpeg, video, VideoFormat::Mp4, 34, 22, 24, 3);
    EXPECT_EQ(namesIn(scratch.path()), std::vector<std::string>{"film.mp4"});
    EXPECT_EQ(headOf(video, 8).substr(4), "ftyp");  // an ISO media file
    if (auto streams = probe(video)) {
        EXPECT_EQ(*streams, "h264,34,22,3");
    }
}

TEST(VideoEncoder, GifOfOddSizeIsPlayable) {
    const auto ffmpeg = ffmpegOnPath();
    if (!ffmpeg) GTEST_SKIP() << "no ffmpeg on PATH";
    ScratchDirectory scratch;
    const fs::path video = scratch.path() / "film.gif";
    encode(*ffmpeg, video, VideoFormat::Gif, 33, 21, 10, 4);
    EXPECT_EQ(headOf(video, 6), "GIF89a");
    if (auto streams = probe(video)) {
        EXPECT_EQ(*streams, "gif,33,21,4");
    }
}

// A frame of another size is refused before it reaches ffmpeg, and the video given up leaves
// no file.
TEST(VideoEncoder, FrameOfAnotherSizeIsAClearErrorAndNoVideo) {
    const auto ffmpeg = ffmpegOnPath();
    if (!ffmpeg) GTEST_SKIP() << "no ffmpeg on PATH";
    ScratchDirectory scratch;
    try {
        VideoEncoder encoder(*ffmpeg, AtomicFile((scratch.path() / "film.mp4").string()),
                             VideoFormat::Mp4, 32, 24, 24);
        encoder.addFrame(solidFrame(32, 24, Rgba{1, 0, 0, 1}));
        encoder.addFrame(solidFrame(16, 16, Rgba{1, 0, 0, 1}));
        ADD_FAILURE() << "a 16x16 frame was taken";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), "--video");
        EXPECT_STREQ(e.what(), "--video: the frames differ in size (16x16 after 32x24)");
    }
    EXPECT_TRUE(namesIn(scratch.path()).empty());
}

// ffmpeg refusing its arguments (a frame rate of 0) is one line, with ffmpeg's own last line,
// and no video and no temporary.
TEST(VideoEncoder, FfmpegRefusingItsArgumentsIsOneLineAndNoVideo) {
    const auto ffmpeg = ffmpegOnPath();
    if (!ffmpeg) GTEST_SKIP() << "no ffmpeg on PATH";
    ScratchDirectory scratch;
    try {
        encode(*ffmpeg, scratch.path() / "film.mp4", VideoFormat::Mp4, 32, 24, 0, 2);
        ADD_FAILURE() << "a film at 0 frames/s was encoded";
    } catch (const UserError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("--video: ffmpeg ", 0), 0u) << message;
        EXPECT_NE(message.find("Invalid argument"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    EXPECT_TRUE(namesIn(scratch.path()).empty());
}

TEST(VideoEncoder, MissingFfmpegIsAClearError) {
    ScratchDirectory scratch;
    const char* path = std::getenv("PATH");
    const std::string savedPath = path != nullptr ? path : "";
    ::setenv("PATH", scratch.path().c_str(), 1);  // a directory without ffmpeg
    EXPECT_THROW(
        {
            try {
                findFfmpeg();
            } catch (const UserError& e) {
                EXPECT_EQ(e.key(), "--video");
                EXPECT_NE(std::string(e.what()).find("there is none on PATH"), std::string::npos);
                throw;
            }
        },
        UserError);
    ::setenv("PATH", savedPath.c_str(), 1);
    const std::string missing = (scratch.path() / "ffmpeg").string();
    try {
        VideoEncoder encoder(missing, AtomicFile((scratch.path() / "film.gif").string()),
                             VideoFormat::Gif, 8, 8, 10);
        ADD_FAILURE() << "a missing ffmpeg was started";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot start " + missing + ": No such file or directory");
    }
    EXPECT_TRUE(namesIn(scratch.path()).empty());
}

}  // namespace
}  // namespace quaternia
