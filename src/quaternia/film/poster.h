// A render cut into units of work for many machines (quaternia-mpi render), and its PNG put
// together again as the units come back, in any order, band by band: the image is never whole
// in memory, and the file is byte for byte what `quaternia render` writes.
//
// A unit is kUnitRows rows by at most kUnitColumns columns; a band is a row of units. Their
// corners are multiples of kWindowAlignment, so that a unit rendered alone has the whole
// image's pixels (RenderOptions::window). No MPI here: the layout, a unit's render and the
// assembly are plain functions, tested on one process.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "quaternia/image/png_stream_writer.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/scene.h"
#include "quaternia/util/atomic_file.h"

namespace quaternia {

inline constexpr int kUnitRows = kWindowAlignment;
inline constexpr int kUnitColumns = 16 * kWindowAlignment;

struct PosterLayout {
    int width = 0, height = 0;
    int64_t unitsAcross = 0, bands = 0;
    PosterLayout(int imageWidth, int imageHeight);
    int64_t units() const { return unitsAcross * bands; }
    int64_t bandOf(int64_t unit) const { return unit / unitsAcross; }
    // The unit's pixels: columns and rows [x0, x1) x [y0, y1).
    Tile window(int64_t unit) const;
};

// How a poster's PNG stores its pixels: colour as the scene asks (RGB for an opaque render,
// RGBA for coverage, which becomes RGB at the end if every pixel turns out opaque, as
// encodePng decides), and the optional 16-bit grey depth pass.
struct PosterFormat {
    int bitDepth = 8;
    bool alpha = false;  // RGBA samples (render.alpha = "coverage")
    bool depth = false;
    static PosterFormat of(const Scene& scene, bool depth);
    size_t colourPixelBytes() const { return size_t((alpha ? 4 : 3) * bitDepth / 8); }
};

// A rendered unit: its rows of PNG samples back to back (colour, then depth where asked), and
// the work it took.
struct PosterUnit {
    int64_t unit = 0;
    std::vector<uint8_t> colour, depth;
    RenderStats stats;
};

// Renders one unit with the options' threads (cancellable: nullopt when cancelled).
std::optional<PosterUnit> renderPosterUnit(const Scene& scene, const PosterLayout& layout,
                                           const PosterFormat& format, int64_t unit,
                                           const RenderOptions& options);

// Rank 0's side: the units' samples in band buffers until a band is whole, then the band's rows
// into the streaming PNG writers, whose bytes go straight to the output files. At most
// windowBands bands are held at once: units of later bands wait (mayStart).
class PosterAssembler {
  public:
    PosterAssembler(const PosterLayout& layout, const PosterFormat& format, AtomicFile& colour,
                    AtomicFile* depth, int64_t windowBands, int threads);
    // Whether `unit` may be handed out now: its band lies within the window of bands after the
    // first band not yet written.
    bool mayStart(int64_t unit) const { return layout_.bandOf(unit) < nextBand_ + windowBands_; }
    // Takes a unit's samples; writes every band that is whole. Throws std::invalid_argument for
    // a unit outside the window or of the wrong size, and UserError when a write fails.
    void add(const PosterUnit& unit);
    bool complete() const { return nextBand_ == layout_.bands; }
    // After the last band: closes the PNG streams. Where the colour was RGBA and every alpha
    // is maximal, writes it again as RGB, into a new temporary for the same path that is
    // returned: commit that one instead of the colour file.
    std::optional<AtomicFile> finish();
    // Bytes of band buffers held at most (the window), for the summary.
    size_t windowBytes() const;

  private:
    struct Band {
        std::vector<uint8_t> colour, depth;
        int64_t unitsMissing = 0;
    };
    void writeBand(Band& band, int64_t index);

    PosterLayout layout_;
    PosterFormat format_;
    int64_t windowBands_;
    int threads_;
    AtomicFile& colourFile_;
    PngStreamWriter colourPng_;
    std::optional<PngStreamWriter> depthPng_;
    std::map<int64_t, Band> pending_;
    int64_t nextBand_ = 0;
    bool everyAlphaMaximal_ = true;
};

}  // namespace quaternia
