// Images in memory: an RGBA image of display values (what the renderer writes and png_io
// encodes), a one-channel float image for depth passes, and a binary mask for comparing
// silhouettes (mask_compare.h). All are row-major with row 0 at the top, like a PNG.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

namespace quaternia {

// One pixel. Colours are display values in [0, 1], already gamma-encoded by the renderer, so
// png_io only quantises them; alpha is the pixel's coverage (the fraction of samples that hit).
struct Rgba {
    float r = 0, g = 0, b = 0, a = 0;
    friend bool operator==(const Rgba&, const Rgba&) = default;
};

// Allocates zeroed memory with calloc and leaves it as it is where a vector would value-
// initialise its elements (which for zero-initialised, implicit-lifetime T such as Rgba is the
// same bytes). Why: a frame-sized vector<Rgba> is zeroed on one thread before the render starts;
// calloc gets large blocks from mmap already zero, so the pages are
// faulted in by the threads that first write them, in parallel, and are still in cache then.
template <class T>
struct ZeroedAllocator {
    using value_type = T;
    ZeroedAllocator() = default;
    template <class U>
    ZeroedAllocator(const ZeroedAllocator<U>&) {}
    T* allocate(std::size_t n) {
        if (void* p = std::calloc(n, sizeof(T))) return static_cast<T*>(p);
        throw std::bad_alloc();
    }
    void deallocate(T* p, std::size_t) { std::free(p); }
    template <class U>
    void construct(U*) {}  // calloc's zero bytes are the value
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    template <class U>
    friend bool operator==(const ZeroedAllocator&, const ZeroedAllocator<U>&) {
        return true;
    }
};

class Image {
  public:
    using Pixels = std::vector<Rgba, ZeroedAllocator<Rgba>>;

    Image() = default;
    // All pixels transparent black. Throws std::invalid_argument for a negative size.
    Image(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    Rgba& at(int x, int y) { return pixels_[index(x, y)]; }
    const Rgba& at(int x, int y) const { return pixels_[index(x, y)]; }
    const Pixels& pixels() const { return pixels_; }

  private:
    std::size_t index(int x, int y) const {
        return std::size_t(y) * std::size_t(width_) + std::size_t(x);
    }

    int width_ = 0, height_ = 0;
    Pixels pixels_;
};

// One float per pixel, e.g. a depth pass normalised to [0, 1].
class GrayImage {
  public:
    GrayImage() = default;
    // All pixels 0. Throws std::invalid_argument for a negative size.
    GrayImage(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    float& at(int x, int y) { return pixels_[index(x, y)]; }
    float at(int x, int y) const { return pixels_[index(x, y)]; }
    const std::vector<float>& pixels() const { return pixels_; }

  private:
    std::size_t index(int x, int y) const {
        return std::size_t(y) * std::size_t(width_) + std::size_t(x);
    }

    int width_ = 0, height_ = 0;
    std::vector<float> pixels_;
};

// A silhouette: inside[y * width + x] is 1 where the pixel belongs to the object, else 0.
struct Mask {
    int width = 0, height = 0;
    std::vector<uint8_t> inside;

    // A mask of the given size with every pixel outside. Throws std::invalid_argument for a
    // negative size.
    static Mask blank(int width, int height);

    bool at(int x, int y) const {
        return inside[std::size_t(y) * std::size_t(width) + std::size_t(x)] != 0;
    }
    void set(int x, int y, bool value) {
        inside[std::size_t(y) * std::size_t(width) + std::size_t(x)] = value ? 1 : 0;
    }
    int64_t count() const;  // pixels inside
};

// Inside where the coverage is strictly above `threshold`: with the default 0.5, a pixel is
// inside when more than half of its samples hit the set.
Mask maskFromAlpha(const Image& image, float threshold = 0.5f);

// Inside where the Rec. 709 luminance is strictly above 0.5: for the reference masks, white
// (255) object on black (0). Alpha is ignored.
Mask maskFromImage(const Image& image);

}  // namespace quaternia
