// `quaternia animate --video`: frames handed as raw RGBA to the ffmpeg executable over a pipe
// (its arguments passed as argv, no shell), encoded into a temporary file beside the output and
// renamed over it once ffmpeg has finished.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "quaternia/image/image.h"
#include "quaternia/util/atomic_file.h"

namespace quaternia {

// H.264 in MP4, VP9 in WebM, or a GIF with a palette made for the film.
enum class VideoFormat { Mp4, WebM, Gif };

// The format `path`'s extension names (.mp4, .webm, .gif, any case); UserError("--video") for
// another.
VideoFormat videoFormatOf(const std::string& path);

// The path of the `ffmpeg` executable on PATH; UserError("--video") where there is none.
std::string findFfmpeg();

// ffmpeg's arguments (argv[1..]) reading width x height RGBA frames at `fps` from standard
// input and writing `format` to `output`. MP4 and WebM are YUV 4:2:0, which needs even sizes:
// an odd width or height gets one black column or row on the right or bottom (pad), so no
// pixel of the film is lost or resampled.
std::vector<std::string> ffmpegArguments(VideoFormat format, int width, int height, double fps,
                                         const std::string& output);

class VideoEncoder {
  public:
    // Starts ffmpeg writing into `output`'s temporary file. Throws UserError when it cannot.
    VideoEncoder(const std::string& ffmpeg, AtomicFile output, VideoFormat format, int width,
                 int height, double fps);
    // Without finish(): ffmpeg is stopped and the temporary removed.
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // The next frame, width x height (else UserError). Throws UserError when ffmpeg has stopped.
    void addFrame(const Image& image);
    // Ends the input, waits for ffmpeg and renames the video into place; UserError when ffmpeg
    // failed.
    void finish();

  private:
    AtomicFile output_;
    int width_, height_;
    // The last line ffmpeg wrote to its standard error ("" if none).
    std::string lastLogLine() const;

    int pipe_ = -1;  // ffmpeg's standard input
    pid_t pid_ = -1;
    int log_ = -1;  // ffmpeg's standard error, kept to name its failure in one line
    std::vector<uint8_t> frame_;
};

}  // namespace quaternia
