#include "quaternia/film/video_encoder.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "quaternia/util/error.h"
#include "quaternia/util/number_format.h"

extern char** environ;

namespace quaternia {

VideoFormat videoFormatOf(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".mp4") return VideoFormat::Mp4;
    if (extension == ".webm") return VideoFormat::WebM;
    if (extension == ".gif") return VideoFormat::Gif;
    throw UserError("--video", "--video '" + path +
                                   "': unknown video format (use .mp4 for H.264, .webm for VP9 "
                                   "or .gif)");
}

std::string findFfmpeg() {
    const char* path = std::getenv("PATH");
    std::string directories = path != nullptr ? path : "";
    for (std::size_t begin = 0; begin <= directories.size();) {
        std::size_t end = std::min(directories.find(':', begin), directories.size());
        std::string directory = directories.substr(begin, end - begin);
        std::string candidate = (directory.empty() ? std::string(".") : directory) + "/ffmpeg";
        struct stat info {};
        if (::stat(candidate.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
            ::access(candidate.c_str(), X_OK) == 0)
            return candidate;
        begin = end + 1;
    }
    throw UserError("--video",
                    "--video needs the ffmpeg executable, and there is none on PATH (install "
                    "ffmpeg, or render the frames without --video)");
}

std::vector<std::string> ffmpegArguments(VideoFormat format, int width, int height, double fps,
                                         const std::string& output) {
    const std::string rate = shortestNumber(fps);  // reads back to the very fps
    std::vector<std::string> args = {
        // -xerror: an output error (a full disk, a file-size limit) that ffmpeg would only
        // log, such as one writing the container's trailer, ends it with a failure instead.
        "-hide_banner",
        "-loglevel",
        "error",
        "-nostats",
        "-xerror",
        "-f",
        "rawvideo",
        "-pix_fmt",
        "rgba",
        "-video_size",
        std::to_string(width) + "x" + std::to_string(height),
        "-framerate",
        rate,
        "-i",
        "pipe:0"};
    const std::vector<std::string> evenSize = {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"};
    std::vector<std::string> codec;
    switch (format) {
        case VideoFormat::Mp4:
            codec = {"-c:v",     "libx264", "-preset",   "medium",     "-crf", "18",
                     "-pix_fmt", "yuv420p", "-movflags", "+faststart", "-f",   "mp4"};
            args.insert(args.end(), evenSize.begin(), evenSize.end());
            break;
        case VideoFormat::WebM:
            codec = {"-c:v",    "libvpx-vp9", "-crf",     "30",      "-b:v", "0",
                     "-row-mt", "1",          "-pix_fmt", "yuv420p", "-f",   "webm"};
            args.insert(args.end(), evenSize.begin(), evenSize.end());
            break;
        case VideoFormat::Gif:
            // One filter graph: a palette made from the whole film, then used on every frame.
            codec = {"-filter_complex",
                     "[0:v]split[a][b];[a]palettegen[p];[b][p]paletteuse",
                     "-loop",
                     "0",
                     "-f",
                     "gif"};
            break;
    }
    args.insert(args.end(), codec.begin(), codec.end());
    args.insert(args.end(), {"-y", output});
    return args;
}

std::string VideoEncoder::lastLogLine() const {
    if (log_ < 0) return "";
    std::string text;
    char buffer[4096];
    ssize_t n;
    for (off_t at = 0; (n = ::pread(log_, buffer, sizeof buffer, at)) > 0; at += n)
        text.append(buffer, size_t(n));
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
        text.pop_back();
    const size_t start = text.find_last_of('\n');
    return start == std::string::npos ? text : text.substr(start + 1);
}

VideoEncoder::VideoEncoder(const std::string& ffmpeg, AtomicFile output, VideoFormat format,
                           int width, int height, double fps)
    : output_(std::move(output)), width_(width), height_(height) {
    std::vector<std::string> args =
        ffmpegArguments(format, width, height, fps, output_.writePath());
    args.insert(args.begin(), ffmpeg);
    std::vector<char*> argv;
    for (std::string& arg : args)
        argv.push_back(arg.data());
    argv.push_back(nullptr);

    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        throw UserError("--video", std::string("cannot start ffmpeg: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    log_ = ::memfd_create("ffmpeg-stderr", MFD_CLOEXEC);
    if (log_ >= 0) posix_spawn_file_actions_adddup2(&actions, log_, STDERR_FILENO);
    // Its own process group: Ctrl-C at the terminal stops the film (which then stops ffmpeg),
    // not ffmpeg under it.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
    int error = ::posix_spawn(&pid_, ffmpeg.c_str(), &actions, &attributes, argv.data(), environ);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    if (error != 0) {
        ::close(fds[1]);
        pid_ = -1;
        throw UserError("--video", "cannot start " + ffmpeg + ": " + std::strerror(error));
    }
    pipe_ = fds[1];
    // A write to a pipe whose reader has gone then fails with EPIPE instead of ending us.
    std::signal(SIGPIPE, SIG_IGN);
    frame_.resize(size_t(width) * size_t(height) * 4);
}

VideoEncoder::~VideoEncoder() {
    if (log_ >= 0) ::close(log_);
    if (pipe_ >= 0) ::close(pipe_);
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
    }
}

void VideoEncoder::addFrame(const Image& image) {
    if (image.width() != width_ || image.height() != height_)
        throw UserError("--video",
                        "--video: the frames differ in size (" + std::to_string(image.width()) +
                            "x" + std::to_string(image.height()) + " after " +
                            std::to_string(width_) + "x" + std::to_string(height_) + ")");
    uint8_t* out = frame_.data();
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const Rgba& p = image.at(x, y);
            for (float v : {p.r, p.g, p.b, p.a})
                *out++ = uint8_t(std::floor(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f));
        }
    for (size_t done = 0; done < frame_.size();) {
        ssize_t n = ::write(pipe_, frame_.data() + done, frame_.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string reason = std::strerror(errno);
            if (pid_ > 0) {  // gone: wait for it, so that what it said is all in the log
                ::close(pipe_);
                pipe_ = -1;
                ::waitpid(pid_, nullptr, 0);
                pid_ = -1;
            }
            const std::string said = lastLogLine();
            throw UserError("--video", "--video: ffmpeg stopped reading frames (" + reason +
                                           (said.empty() ? "" : ": " + said) + ")");
        }
        done += size_t(n);
    }
}

void VideoEncoder::finish() {
    ::close(pipe_);
    pipe_ = -1;
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        const std::string said = lastLogLine();
        throw UserError("--video",
                        "--video: ffmpeg failed (" +
                            (WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                               : "signal " + std::to_string(WTERMSIG(status))) +
                            (said.empty() ? "" : ": " + said) + "); no video written");
    }
    output_.commit();
}

}  // namespace quaternia
