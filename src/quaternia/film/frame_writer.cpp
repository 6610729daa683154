#include "quaternia/film/frame_writer.h"

#include <utility>

#include "quaternia/image/png_io.h"
#include "quaternia/render/render_png.h"
#include "quaternia/util/atomic_file.h"

namespace quaternia {

FrameWriter::FrameWriter(Handler handler, std::size_t capacity)
    : handler_(std::move(handler)), capacity_(capacity), thread_([this] { run(); }) {}

FrameWriter::~FrameWriter() {
    {
        std::lock_guard lock(mutex_);
        closing_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void FrameWriter::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return !queue_.empty() || closing_; });
        if (queue_.empty()) return;
        FrameWork work = std::move(queue_.front());
        queue_.pop_front();
        busy_ = true;
        changed_.notify_all();
        lock.unlock();
        std::exception_ptr error;
        try {
            if (!error_) handler_(work);
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        if (error && !error_) error_ = error;
        busy_ = false;
        changed_.notify_all();
    }
}

void FrameWriter::rethrow() {
    if (error_) std::rethrow_exception(error_);
}

void FrameWriter::push(FrameWork work) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return queue_.size() < capacity_ || error_; });
    rethrow();
    queue_.push_back(std::move(work));
    changed_.notify_all();
}

void FrameWriter::finish() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return (queue_.empty() && !busy_) || error_; });
    rethrow();
}

FrameWriter::Handler frameFileHandler(const FrameDirectory& directory, VideoEncoder* encoder) {
    return [directory, encoder](FrameWork& work) {
        const std::string path = directory.framePath(work.frame);
        if (work.rendered) {
            std::vector<uint8_t> png = encodeRenderPng(*work.rendered, work.bitDepth);
            work.rendered.reset();  // the samples go before the PNG is decoded for the encoder
            writeFileAtomically(path, png);
            if (encoder != nullptr) encoder->addFrame(decodePng(png));
        } else if (encoder != nullptr) {
            encoder->addFrame(readPng(path));
        }
    };
}

}  // namespace quaternia
