#include "image.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace quaternia {

namespace {

// Blocks from this size on are mapped on their own, in transparent huge pages where the kernel
// gives them to madvise (Debian's default): a 1080p frame of float RGBA (33 MB) then takes 16
// page faults instead of 8100, which cost about 1.5% of a case01 render. Smaller blocks come
// from calloc.
constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kMappedFrom = 2 * kHugePage;

// The mapping of `bytes` with room to align its start to a huge page.
std::size_t mappedLength(std::size_t bytes) {
    return bytes + kHugePage;
}

}  // namespace

// AddressSanitizer sees overflows only in memory from its own allocator.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kMapLargeBlocks = false;
#else
constexpr bool kMapLargeBlocks = true;
#endif

void* zeroedAllocate(std::size_t bytes) {
    if (!kMapLargeBlocks || bytes < kMappedFrom) {
        if (void* p = std::calloc(bytes == 0 ? 1 : bytes, 1)) return p;
        throw std::bad_alloc();
    }
    // Anonymous mappings are zero. The block starts at the first huge-page boundary of the
    // mapping; the part before it and the tail past the block are unmapped again.
    const std::size_t length = mappedLength(bytes);
    void* mapped =
        mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t aligned = (start + kHugePage - 1) & ~std::uintptr_t(kHugePage - 1);
    if (aligned > start) munmap(mapped, aligned - start);
    const std::uintptr_t end = start + length, blockEnd = aligned + bytes;
    const std::uintptr_t pageEnd = (blockEnd + 4095) & ~std::uintptr_t(4095);
    if (end > pageEnd) munmap(reinterpret_cast<void*>(pageEnd), end - pageEnd);
    void* block = reinterpret_cast<void*>(aligned);
    madvise(block, bytes, MADV_HUGEPAGE);  // a hint: without huge pages it still works
    return block;
}

void zeroedFree(void* p, std::size_t bytes) {
    if (p == nullptr) return;
    if (!kMapLargeBlocks || bytes < kMappedFrom) {
        std::free(p);
        return;
    }
    munmap(p, bytes);
}

namespace {

size_t checkedPixelCount(int width, int height) {
    if (width < 0 || height < 0)
        throw std::invalid_argument("image size must not be negative, got " +
                                    std::to_string(width) + "x" + std::to_string(height));
    return size_t(width) * size_t(height);
}

}  // namespace

Image::Image(int width, int height)
    : width_(width), height_(height), pixels_(checkedPixelCount(width, height)) {}

GrayImage::GrayImage(int width, int height)
    : width_(width), height_(height), pixels_(checkedPixelCount(width, height)) {}

Mask Mask::blank(int width, int height) {
    Mask mask;
    mask.inside.assign(checkedPixelCount(width, height), 0);
    mask.width = width;
    mask.height = height;
    return mask;
}

int64_t Mask::count() const {
    return std::count_if(inside.begin(), inside.end(), [](uint8_t v) { return v != 0; });
}

Mask maskFromAlpha(const Image& image, float threshold) {
    Mask mask = Mask::blank(image.width(), image.height());
    const Image::Pixels& pixels = image.pixels();
    for (size_t i = 0; i < pixels.size(); ++i)
        mask.inside[i] = pixels[i].a > threshold ? 1 : 0;
    return mask;
}

Mask maskFromImage(const Image& image) {
    Mask mask = Mask::blank(image.width(), image.height());
    const Image::Pixels& pixels = image.pixels();
    for (size_t i = 0; i < pixels.size(); ++i) {
        const Rgba& p = pixels[i];
        // Rec. 709 weights; on a gray image this is the gray value itself.
        float luminance = 0.2126f * p.r + 0.7152f * p.g + 0.0722f * p.b;
        mask.inside[i] = luminance > 0.5f ? 1 : 0;
    }
    return mask;
}

}  // namespace quaternia
