// The thread that writes a film's frames while the next one renders: frames are handed over in
// order through a queue of at most `capacity` of them (each a whole frame's samples, so the
// queue bounds the memory), and handled in that order. frameFileHandler is what a film does
// with each: its PNG file, and the video encoder's frame.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

#include "quaternia/film/frame_plan.h"
#include "quaternia/film/video_encoder.h"
#include "quaternia/render/render.h"

namespace quaternia {

struct FrameWork {
    int64_t frame = 0;
    std::optional<RenderResult> rendered;  // none: the frame's file exists already
    int bitDepth = 8;                      // the frame's render.bit_depth
};

class FrameWriter {
  public:
    using Handler = std::function<void(FrameWork&)>;
    FrameWriter(Handler handler, std::size_t capacity);
    // Stops the thread after the frames handed over so far (without rethrowing).
    ~FrameWriter();
    FrameWriter(const FrameWriter&) = delete;
    FrameWriter& operator=(const FrameWriter&) = delete;

    // Waits while the queue is full, then queues the frame. Rethrows the first error of the
    // handler (the frames after it are not handled).
    void push(FrameWork work);
    // Waits until every frame handed over has been handled; rethrows the handler's error.
    void finish();

  private:
    void run();
    void rethrow();

    Handler handler_;
    std::size_t capacity_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<FrameWork> queue_;
    bool busy_ = false, closing_ = false;
    std::exception_ptr error_;
    std::thread thread_;
};

// A film's handler: a rendered frame's PNG written whole to its file in `directory` (renamed
// into place, so that a failed write leaves the old file or none, never half of one) and, where
// there is an encoder, handed to it; a frame not rendered (its file exists) is read back for the
// encoder. The encoder, if any, must outlive the handler's use.
FrameWriter::Handler frameFileHandler(const FrameDirectory& directory, VideoEncoder* encoder);

}  // namespace quaternia
