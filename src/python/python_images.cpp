// render, render_passes, plane and encode_png: images as NumPy arrays.
#include <cstring>

#include "python/python_module.h"
#include "quaternia/image/png_io.h"
#include "quaternia/image/png_lanes.h"
#include "quaternia/image/png_writer.h"
#include "quaternia/plane/plane_render.h"
#include "quaternia/render/environment.h"
#include "quaternia/render/pixel_certificate.h"
#include "quaternia/render/render.h"
#include "quaternia/render/render_png.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

namespace quaternia::python {
namespace {

// The image's pixels as its PNG's samples (png_lanes.h, the PNG writer's own quantisation),
// RGBA, in an array (height, width, 4) of uint8 or uint16 (native byte order).
py::array quantisedArray(const Image& image, int bitDepth) {
    const py::ssize_t width = image.width(), height = image.height();
    const size_t pixels = size_t(width) * size_t(height);
    const float* rgba = reinterpret_cast<const float*>(image.pixels().data());
    if (bitDepth == 8) {
        py::array_t<uint8_t> array({height, width, py::ssize_t(4)});
        uint8_t* out = array.mutable_data();
        {
            py::gil_scoped_release release;
            quantisePngSamples(rgba, pixels, 8, true, out);
        }
        return array;
    }
    py::array_t<uint16_t> array({height, width, py::ssize_t(4)});
    uint16_t* out = array.mutable_data();
    {
        py::gil_scoped_release release;
        uint8_t* bytes = reinterpret_cast<uint8_t*>(out);
        quantisePngSamples(rgba, pixels, 16, true, bytes);
        for (size_t i = 0; i < 4 * pixels; ++i)  // PNG's big-endian samples to numbers
            out[i] = uint16_t(uint16_t(bytes[2 * i]) << 8 | bytes[2 * i + 1]);
    }
    return array;
}

Scene renderScene(const Scene& scene, std::optional<int64_t> width, std::optional<int64_t> height,
                  std::optional<int64_t> samples) {
    Scene result = withOverrides(
        scene, {{"render.width", width}, {"render.height", height}, {"render.samples", samples}});
    validateScene(result);
    return result;
}

void requireImageMemory(const Scene& scene, uint64_t bytes,
                        const std::optional<std::string>& budget, int threads) {
    requireMemoryOrRaise(bytes, budget, threads, "render.width",
                         "render.width x render.height = " + std::to_string(scene.render.width) +
                             " x " + std::to_string(scene.render.height) + ": the image",
                         "lower render.width and render.height, or pass memory_budget");
}

// The render of `scene` on `workers` threads (0: every core), with the passes where asked.
RenderResult renderOf(const Scene& scene, int workers, const py::object& progress, bool passes) {
    return runWithoutGil(workers, progress, [&](const WorkOptions& work) {
        RenderOptions options;
        static_cast<WorkOptions&>(options) = work;
        options.passes = passes;
        return render(scene, options);
    });
}

py::array renderImage(const Scene& scene, std::optional<int64_t> width,
                      std::optional<int64_t> height, std::optional<int64_t> samples,
                      std::optional<int> threads, std::optional<int> bitDepth, bool linear,
                      const py::object& progress, const std::optional<std::string>& memoryBudget) {
    const Scene s = renderScene(scene, width, height, samples);
    const int bits = bitDepth.value_or(s.render.bitDepth);
    if (bits != 8 && bits != 16)
        throw UserError("bit_depth", "bit_depth must be 8 or 16, got " + std::to_string(bits));
    const int workers = threadsOf(threads);
    const uint64_t pixels = uint64_t(s.render.width) * uint64_t(s.render.height);
    // The float image, the passes' linear colour where asked, and the array.
    requireImageMemory(s, pixels * (sizeof(Rgba) * (linear ? 2 : 1) + 4 * sizeof(uint16_t)),
                       memoryBudget, workers);
    // The environment map read (and checked) here, before the work: ValueError, MemoryError.
    environmentOf(s, memoryBudgetOf(memoryBudget, workers));
    requireFractalMemory(s, memoryBudgetOf(memoryBudget, workers));
    RenderResult result = renderOf(s, workers, progress, linear);
    if (linear) {
        const py::ssize_t w = s.render.width, h = s.render.height;
        return adoptArray<float>(std::move(result.passes.linear), {h, w, 4});
    }
    return quantisedArray(result.image, bits);
}

py::dict renderPasses(const Scene& scene, std::optional<int64_t> width,
                      std::optional<int64_t> height, std::optional<int64_t> samples,
                      std::optional<int> threads, const py::object& progress,
                      const std::optional<std::string>& memoryBudget) {
    const Scene s = renderScene(scene, width, height, samples);
    const int workers = threadsOf(threads);
    const uint64_t pixels = uint64_t(s.render.width) * uint64_t(s.render.height);
    requireImageMemory(s, pixels * (2 * sizeof(Rgba) + 6 * sizeof(float) + 4 * sizeof(uint16_t)),
                       memoryBudget, workers);
    // The environment map read (and checked) here, before the work: ValueError, MemoryError.
    environmentOf(s, memoryBudgetOf(memoryBudget, workers));
    requireFractalMemory(s, memoryBudgetOf(memoryBudget, workers));
    RenderResult result = renderOf(s, workers, progress, true);
    const py::ssize_t w = s.render.width, h = s.render.height;
    py::dict passes;
    passes["image"] = quantisedArray(result.image, s.render.bitDepth);
    passes["linear"] = adoptArray<float>(std::move(result.passes.linear), {h, w, 4});
    passes["depth"] = adoptArray<float>(std::move(result.passes.distance), {h, w});
    passes["normal"] = adoptArray<float>(std::move(result.passes.normal), {h, w, 3});
    passes["trap"] = adoptArray<float>(std::move(result.passes.trap), {h, w});
    passes["id"] = adoptArray<uint32_t>(std::move(result.passes.object), {h, w});
    return passes;
}

py::dict certifyImage(const Scene& scene, std::optional<int64_t> width,
                      std::optional<int64_t> height, std::optional<int> threads,
                      const py::object& progress, const std::optional<std::string>& memoryBudget) {
    const Scene s = renderScene(scene, width, height, std::nullopt);
    validateCertificate(s);
    const int workers = threadsOf(threads);
    const uint64_t pixels = uint64_t(s.render.width) * uint64_t(s.render.height);
    requireImageMemory(s, pixels * (1 + 2 * sizeof(float)), memoryBudget, workers);
    requireFractalMemory(s, memoryBudgetOf(memoryBudget, workers));
    PixelCertificate c = runWithoutGil(
        workers, progress, [&](const WorkOptions& work) { return certifyPixels(s, work); });
    const py::ssize_t w = s.render.width, h = s.render.height;
    py::dict out;
    out["classes"] = adoptArray<uint8_t>(std::move(c.classes), {h, w});
    out["nearest"] = adoptArray<float>(std::move(c.nearestHit), {h, w});
    out["farthest"] = adoptArray<float>(std::move(c.farthestHit), {h, w});
    out["missed"] = c.counts.missed;
    out["hit"] = c.counts.hit;
    out["undecided"] = c.counts.undecided;
    out["undecided_fraction"] = c.counts.undecidedFraction();
    out["proofs"] = c.proofs;
    out["seconds"] = c.seconds;
    return out;
}

py::tuple planeImage(const Scene& scene, const std::optional<std::string>& kind,
                     std::optional<int64_t> width, std::optional<int64_t> height,
                     std::optional<int64_t> samples, std::optional<int> threads,
                     const py::object& progress, const std::optional<std::string>& memoryBudget) {
    Scene s = withOverrides(
        scene, {{"render.width", width}, {"render.height", height}, {"render.samples", samples}});
    if (kind) setParameter(s, "plane.kind", *kind);
    validatePlaneScene(s);
    const int workers = threadsOf(threads);
    requireImageMemory(s, planeMemoryBytes(s), memoryBudget, workers);
    requireFractalMemory(s, memoryBudgetOf(memoryBudget, workers));
    PlaneImage plane = runWithoutGil(workers, progress,
                                     [&](const WorkOptions& work) { return renderPlane(s, work); });
    const py::ssize_t w = s.render.width, h = s.render.height;
    py::array image = quantisedArray(plane.image, s.render.bitDepth);
    return py::make_tuple(image, adoptArray<int32_t>(std::move(plane.labels), {h, w}));
}

// An array (height, width, 4) of uint8 or uint16 as PNG bytes: RGB where every alpha is the
// largest sample (as the renderer writes opaque images), else RGBA.
py::bytes encodePngArray(const py::array& input) {
    if (input.ndim() != 3 || input.shape(2) != 4)
        throw UserError("image", "encode_png takes an array (height, width, 4)");
    const bool sixteen = py::isinstance<py::array_t<uint16_t>>(input) &&
                         input.dtype().equal(py::dtype::of<uint16_t>());
    if (!sixteen && !input.dtype().equal(py::dtype::of<uint8_t>()))
        throw UserError("image", "encode_png takes uint8 or uint16 samples");
    const py::array array = py::array::ensure(input, py::array::c_style);
    const size_t width = size_t(array.shape(1)), height = size_t(array.shape(0));
    if (width == 0 || height == 0) throw UserError("image", "encode_png: the image is empty");
    const int bytes = sixteen ? 2 : 1;
    const size_t samples = width * height * 4;
    const uint8_t* raw = static_cast<const uint8_t*>(array.data());
    std::vector<uint8_t> png;
    {
        py::gil_scoped_release release;
        const uint16_t maximum = sixteen ? 65535 : 255;
        bool opaque = true;
        for (size_t i = 3; i < samples && opaque; i += 4) {
            const uint16_t a = sixteen ? reinterpret_cast<const uint16_t*>(raw)[i] : raw[i];
            opaque = a == maximum;
        }
        const int channels = opaque ? 3 : 4;
        std::vector<uint8_t> rows(width * height * size_t(channels * bytes));
        size_t o = 0;
        for (size_t i = 0; i < samples; ++i) {
            if (opaque && i % 4 == 3) continue;
            if (sixteen) {
                const uint16_t v = reinterpret_cast<const uint16_t*>(raw)[i];
                rows[o++] = uint8_t(v >> 8), rows[o++] = uint8_t(v & 0xff);
            } else {
                rows[o++] = raw[i];
            }
        }
        const PngFormat format{int(width), int(height), 8 * bytes,
                               opaque ? PngColorType::Rgb : PngColorType::Rgba};
        png = writePngBytes(format, rows);
    }
    return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
}

// A PNG file's samples as stored (PngRowReader): (height, width, channels) of uint8 or uint16.
py::array pngSamples(const std::string& path) {
    try {
        PngRowReader reader(path);
        const PngFormat format = reader.format();
        const py::ssize_t channels = pngChannels(format.colorType);
        const std::vector<py::ssize_t> shape{format.height, format.width, channels};
        std::vector<uint8_t> row(pngRowBytes(format));
        if (format.bitDepth == 8) {
            py::array_t<uint8_t> array(shape);
            for (int y = 0; y < format.height; ++y)
                reader.readRow(std::span<uint8_t>(array.mutable_data(y), row.size()));
            return array;
        }
        py::array_t<uint16_t> array(shape);
        for (int y = 0; y < format.height; ++y) {
            reader.readRow(row);
            uint16_t* out = array.mutable_data(y);
            for (size_t i = 0; i < row.size() / 2; ++i)
                out[i] = uint16_t(uint16_t(row[2 * i]) << 8 | row[2 * i + 1]);
        }
        return array;
    } catch (const std::runtime_error& error) {
        raiseOSError(error.what());
    }
}

}  // namespace

void bindImages(py::module_& module) {
    module.def("read_png", &pngSamples, py::arg("path"),
               "A PNG file's samples as stored, (height, width, channels) of uint8 or uint16 "
               "(8-bit and 16-bit gray, RGB or RGBA files, not interlaced).");
    module.def("render", &renderImage, py::arg("scene"), py::arg("width") = py::none(),
               py::arg("height") = py::none(), py::arg("samples") = py::none(),
               py::arg("threads") = py::none(), py::kw_only(), py::arg("bit_depth") = py::none(),
               py::arg("linear") = false, py::arg("progress") = py::none(),
               py::arg("memory_budget") = py::none(),
               R"(Renders the scene; width, height and samples override render.width, ...

Returns an array (height, width, 4): by default uint8 (or uint16 where
render.bit_depth or bit_depth is 16), the very samples of the PNG that
`quaternia render` writes for the scene (alpha 255 where render.alpha is opaque).
linear=True gives float32 linear colour before exposure and gamma, straight alpha.
threads: 0 or None for every core. progress: called with the fraction done.
memory_budget: "512M", "8G", "unlimited"; by default the memory available.
The GIL is released while it renders; Ctrl-C (KeyboardInterrupt) stops it.)");
    module.def("render_passes", &renderPasses, py::arg("scene"), py::arg("width") = py::none(),
               py::arg("height") = py::none(), py::arg("samples") = py::none(),
               py::arg("threads") = py::none(), py::kw_only(), py::arg("progress") = py::none(),
               py::arg("memory_budget") = py::none(),
               R"(Renders the scene with the passes the EXR writer stores, as a dict of arrays:
image (as render), linear (h, w, 4) float32, depth (h, w) float32 (distance from
the camera along the ray; 1e10 where nothing was hit), normal (h, w, 3) float32
(world, unit; 0 where nothing was hit), trap (h, w) float32 (orbit trap min |z_n|),
id (h, w) uint32 (0 nothing, 1 the set, 2 the ground).)");
    module.def("certify", &certifyImage, py::arg("scene"), py::arg("width") = py::none(),
               py::arg("height") = py::none(), py::arg("threads") = py::none(), py::kw_only(),
               py::arg("progress") = py::none(), py::arg("memory_budget") = py::none(),
               R"(The certificate of the scene's picture, as `quaternia render --certify`
writes it (docs/certificates.md): a dict with classes (h, w) uint8 (0 the pixel's
footprint certainly misses K_N, 255 its central ray certainly meets it, 128
undecided), nearest and farthest (h, w) float32 (for certain hits, the distances
between which the central ray first meets K_N; 1e10 elsewhere), and the counts
missed, hit, undecided, undecided_fraction, proofs and seconds. A formula part
with no interval extension, or a thin lens, raises ValueError naming the key.)");
    module.def("plane", &planeImage, py::arg("scene"), py::arg("kind") = py::none(),
               py::arg("width") = py::none(), py::arg("height") = py::none(),
               py::arg("samples") = py::none(), py::arg("threads") = py::none(), py::kw_only(),
               py::arg("progress") = py::none(), py::arg("memory_budget") = py::none(),
               R"(The 2D image of `quaternia plane`: kind is plane.kind ("julia",
"julia-boundary", "mandelbrot", "basins", "slice"). Returns (image, labels):
the image as render's array, and per pixel (of its first sample) an int32 label:
the escape iteration (-1 where the orbit stayed) for the escape kinds, the basin
for basins (the attracting cycle's index, -1 escaping, -2 undecided).)");
    module.def("encode_png", &encodePngArray, py::arg("image"),
               "PNG bytes of an array (height, width, 4) of uint8 or uint16: RGB where every "
               "alpha is the largest sample (as `quaternia render` writes opaque images).");
}

}  // namespace quaternia::python
