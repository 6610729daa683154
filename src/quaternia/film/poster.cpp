#include "quaternia/film/poster.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "quaternia/image/png_io.h"
#include "quaternia/image/png_lanes.h"
#include "quaternia/image/png_writer.h"

namespace quaternia {

PosterLayout::PosterLayout(int imageWidth, int imageHeight)
    : width(imageWidth),
      height(imageHeight),
      unitsAcross((imageWidth + kUnitColumns - 1) / kUnitColumns),
      bands((imageHeight + kUnitRows - 1) / kUnitRows) {}

Tile PosterLayout::window(int64_t unit) const {
    const int x0 = int(unit % unitsAcross) * kUnitColumns, y0 = int(bandOf(unit)) * kUnitRows;
    return Tile{x0, y0, std::min(width, x0 + kUnitColumns), std::min(height, y0 + kUnitRows)};
}

PosterFormat PosterFormat::of(const Scene& scene, bool depth) {
    return PosterFormat{scene.render.bitDepth, scene.render.alpha == AlphaMode::Coverage, depth};
}

std::optional<PosterUnit> renderPosterUnit(const Scene& scene, const PosterLayout& layout,
                                           const PosterFormat& format, int64_t unit,
                                           const RenderOptions& options) {
    RenderOptions unitOptions = options;
    const Tile window = layout.window(unit);
    unitOptions.window = window;
    unitOptions.opaquePngPixels = true;  // an opaque render comes as its PNG pixels
    unitOptions.depth = format.depth;
    RenderResult result = render(scene, unitOptions);
    if (!result.completed) return std::nullopt;
    PosterUnit out;
    out.unit = unit;
    out.stats = result.stats;
    const size_t width = size_t(window.x1 - window.x0), rows = size_t(window.y1 - window.y0);
    if (!result.pngPixels.empty()) {
        out.colour.assign(result.pngPixels.begin(), result.pngPixels.end());
    } else {
        // Coverage: the float image's rows quantised with alpha, as encodePng does.
        const size_t rowBytes = width * format.colourPixelBytes();
        out.colour.resize(rowBytes * rows);
        for (size_t y = 0; y < rows; ++y)
            quantisePngSamples(&result.image.at(0, int(y)).r, width, format.bitDepth, true,
                               out.colour.data() + y * rowBytes);
    }
    if (format.depth) {
        out.depth.resize(width * rows * 2);
        quantiseGray16(result.depth.pixels().data(), width * rows, out.depth.data());
    }
    return out;
}

namespace {

PngFormat colourFormat(const PosterLayout& layout, const PosterFormat& format, bool alpha) {
    return PngFormat{layout.width, layout.height, format.bitDepth,
                     alpha ? PngColorType::Rgba : PngColorType::Rgb};
}

PngSink sinkInto(AtomicFile& file) {
    return [&file](std::span<const uint8_t> bytes) { file.write(bytes.data(), bytes.size()); };
}

// Whether every alpha sample of RGBA rows is the maximum of its bit depth.
bool alphaAllMaximal(const std::vector<uint8_t>& rgba, int bitDepth) {
    const size_t sampleBytes = size_t(bitDepth / 8), pixelBytes = 4 * sampleBytes;
    for (size_t at = 3 * sampleBytes; at < rgba.size(); at += pixelBytes) {
        if (rgba[at] != 0xff || (sampleBytes == 2 && rgba[at + 1] != 0xff)) return false;
    }
    return true;
}

}  // namespace

PosterAssembler::PosterAssembler(const PosterLayout& layout, const PosterFormat& format,
                                 AtomicFile& colour, AtomicFile* depth, int64_t windowBands,
                                 int threads)
    : layout_(layout),
      format_(format),
      windowBands_(std::max<int64_t>(1, windowBands)),
      threads_(threads),
      colourFile_(colour),
      colourPng_(colourFormat(layout, format, format.alpha), sinkInto(colour), threads) {
    if (depth != nullptr)
        depthPng_.emplace(PngFormat{layout.width, layout.height, 16, PngColorType::Gray},
                          sinkInto(*depth), threads);
}

size_t PosterAssembler::windowBytes() const {
    const size_t rowPixels = size_t(layout_.width) * size_t(kUnitRows);
    return size_t(windowBands_) * rowPixels *
           (format_.colourPixelBytes() + (format_.depth ? 2 : 0));
}

void PosterAssembler::add(const PosterUnit& unit) {
    if (unit.unit < 0 || unit.unit >= layout_.units() || !mayStart(unit.unit) ||
        layout_.bandOf(unit.unit) < nextBand_)
        throw std::invalid_argument("poster unit " + std::to_string(unit.unit) + " is not awaited");
    const Tile window = layout_.window(unit.unit);
    const size_t width = size_t(window.x1 - window.x0), rows = size_t(window.y1 - window.y0);
    const size_t pixelBytes = format_.colourPixelBytes();
    if (unit.colour.size() != width * rows * pixelBytes ||
        unit.depth.size() != (format_.depth ? width * rows * 2 : 0))
        throw std::invalid_argument("poster unit " + std::to_string(unit.unit) +
                                    " has the wrong size");
    const int64_t index = layout_.bandOf(unit.unit);
    auto [at, fresh] = pending_.try_emplace(index);
    Band& band = at->second;
    const size_t bandRowPixels = size_t(layout_.width);
    if (fresh) {
        band.colour.resize(bandRowPixels * rows * pixelBytes);
        if (format_.depth) band.depth.resize(bandRowPixels * rows * 2);
        band.unitsMissing = layout_.unitsAcross;
    }
    for (size_t y = 0; y < rows; ++y) {
        std::memcpy(band.colour.data() + (y * bandRowPixels + size_t(window.x0)) * pixelBytes,
                    unit.colour.data() + y * width * pixelBytes, width * pixelBytes);
        if (format_.depth)
            std::memcpy(band.depth.data() + (y * bandRowPixels + size_t(window.x0)) * 2,
                        unit.depth.data() + y * width * 2, width * 2);
    }
    if (format_.alpha && everyAlphaMaximal_)
        everyAlphaMaximal_ = alphaAllMaximal(unit.colour, format_.bitDepth);
    --band.unitsMissing;
    // Every whole band from the next one on goes to the files, in order.
    for (auto next = pending_.find(nextBand_);
         next != pending_.end() && next->second.unitsMissing == 0;
         next = pending_.find(nextBand_)) {
        writeBand(next->second, nextBand_);
        pending_.erase(next);
        ++nextBand_;
    }
}

void PosterAssembler::writeBand(Band& band, int64_t index) {
    const Tile first = layout_.window(index * layout_.unitsAcross);
    const size_t rows = size_t(first.y1 - first.y0);
    colourPng_.addRows(band.colour, rows);
    if (depthPng_) depthPng_->addRows(band.depth, rows);
}

std::optional<AtomicFile> PosterAssembler::finish() {
    if (!complete()) throw std::logic_error("the poster's bands are not all written");
    colourPng_.finish();
    if (depthPng_) depthPng_->finish();
    // encodePng stores an image whose every alpha is maximal as RGB: read the RGBA stream back
    // row by row and write it again without alpha. A device or pipe cannot be read back: it
    // keeps the RGBA stream (the same pixels).
    if (!format_.alpha || !everyAlphaMaximal_ || colourFile_.isDirect()) return std::nullopt;
    AtomicFile rgb(colourFile_.path());
    PngStreamWriter rgbPng(colourFormat(layout_, format_, false), sinkInto(rgb), threads_);
    PngRowReader reader(colourFile_.temporaryPath());
    const size_t sampleBytes = size_t(format_.bitDepth / 8), width = size_t(layout_.width);
    std::vector<uint8_t> rgba(width * 4 * sampleBytes), row(width * 3 * sampleBytes);
    for (int y = 0; y < layout_.height; ++y) {
        reader.readRow(rgba);
        for (size_t x = 0; x < width; ++x)
            std::memcpy(row.data() + x * 3 * sampleBytes, rgba.data() + x * 4 * sampleBytes,
                        3 * sampleBytes);
        rgbPng.addRows(row, 1);
    }
    rgbPng.finish();
    return rgb;
}

}  // namespace quaternia
