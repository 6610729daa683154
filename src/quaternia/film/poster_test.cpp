#include "quaternia/film/poster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "quaternia/image/png_io.h"
#include "quaternia/render/render_png.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/test_scenes.h"
#include "quaternia/util/test_scratch_path.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

// The units of a poster cover its pixels once each, aligned for RenderOptions::window.
TEST(Poster, UnitsCoverTheImageOnceAligned) {
    const PosterLayout layout(2100, 130);
    EXPECT_EQ(layout.unitsAcross, 3);
    EXPECT_EQ(layout.bands, 3);
    std::vector<int> covered(2100 * 130);
    for (int64_t unit = 0; unit < layout.units(); ++unit) {
        const Tile w = layout.window(unit);
        EXPECT_EQ(w.x0 % kWindowAlignment, 0);
        EXPECT_EQ(w.y0 % kWindowAlignment, 0);
        EXPECT_EQ(layout.bandOf(unit), w.y0 / kUnitRows);
        for (int y = w.y0; y < w.y1; ++y)
            for (int x = w.x0; x < w.x1; ++x)
                ++covered[size_t(y) * 2100 + size_t(x)];
    }
    EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int n) { return n == 1; }));
}

// Units rendered alone and handed to the assembler out of order make the PNG (and depth PNG)
// of the whole render, byte for byte: opaque RGB, coverage RGBA at 16 bits, and coverage where
// every pixel is covered (which encodePng stores as RGB).
TEST(Poster, AssembledFromUnitsInAnyOrderIsTheRendersPng) {
    struct Case {
        AlphaMode alpha;
        int bitDepth;
        bool fillFrame;
    };
    const fs::path dir = testing::scratchPath("quaternia_poster_test");
    fs::create_directories(dir);
    for (const Case& c : {Case{AlphaMode::Opaque, 8, false}, Case{AlphaMode::Coverage, 16, false},
                          Case{AlphaMode::Coverage, 8, true}}) {
        Scene scene = c.fillFrame ? testing::unitBallScene(1100, 140) : defaultScene();
        scene.render.width = 1100;
        scene.render.height = 140;
        scene.render.alpha = c.alpha;
        scene.render.bitDepth = c.bitDepth;
        if (c.fillFrame) scene.camera.fovDegrees = 5;  // the ball fills the frame
        RenderOptions whole;
        whole.depth = true;
        whole.threads = 2;
        const PngRender expected = renderPng(scene, whole);

        const PosterLayout layout(1100, 140);
        const PosterFormat format = PosterFormat::of(scene, true);
        const std::string path = (dir / "poster.png").string(),
                          depthPath = (dir / "depth.png").string();
        AtomicFile colour(path), depth(depthPath);
        PosterAssembler assembler(layout, format, colour, &depth, 2, 2);
        EXPECT_FALSE(assembler.mayStart(4));  // band 2: beyond the window of 2 bands
        EXPECT_THROW(assembler.add(PosterUnit{4, {}, {}, {}}), std::invalid_argument);
        // Last unit of each band first, the window's later band before the earlier one.
        for (int64_t unit : {3, 2, 1, 0, 5, 4}) {
            ASSERT_TRUE(assembler.mayStart(unit));
            RenderOptions options;
            options.threads = 2;
            auto rendered = renderPosterUnit(scene, layout, format, unit, options);
            ASSERT_TRUE(rendered.has_value());
            assembler.add(*rendered);
        }
        ASSERT_TRUE(assembler.complete());
        std::optional<AtomicFile> rgb = assembler.finish();
        EXPECT_EQ(rgb.has_value(), c.fillFrame);
        (rgb ? *rgb : colour).commit();
        depth.commit();
        EXPECT_EQ(fileBytes(path), expected.png) << int(c.alpha) << " " << c.bitDepth;
        EXPECT_EQ(fileBytes(depthPath), expected.depthPng);
        if (!c.fillFrame) {
            const Image image = readPng(path);
            std::set<float> alphas;
            for (const Rgba& p : image.pixels())
                alphas.insert(p.a);
            EXPECT_EQ(alphas.size() > 1, c.alpha == AlphaMode::Coverage);
        }
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace quaternia
