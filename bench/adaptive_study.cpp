// quaternia_adaptive_study: what adaptive anti-aliasing can save on a scene (issue 17, part 3).
//   quaternia_adaptive_study [SCENE.toml] [--width W] [--height H] [--samples N] [--runs R]
// Renders the scene's N samples per pixel one at a time (RenderOptions::onlySample), so that
// the value of any subset of a pixel's samples is known, and the uniform render of all N. Then
// against the uniform render, in display values (1/255, every channel, alpha too), as
// quaternia_image_difference compares PNGs:
//  - the oracle: each pixel's fewest samples, taken in AdaptiveSampling's order, whose value
//    lies within 24/255 of the uniform one: what a sampler that knew where to refine would take;
//  - a family of detection rules shaped as adaptive_sampling.cpp's (neighbours' first samples
//    compared with a threshold for 4 samples and one for all N, then a 4-sample pixel whose later
//    samples differ from its first by more than a third threshold takes all N), also with 2
//    first samples per pixel (compared with each other as well): the samples each takes and
//    its error;
//  - time: one sample, adaptive and uniform renders (medians of R), a refined sample's cost
//    against a first sample's, and each rule's projected time in units of one sample.
// The default is the embedded default scene at 1920x1080 with 16 samples.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "quaternia/render/adaptive_sampling.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"

namespace {

using namespace quaternia;

struct Display {
    float c[4];
};

// The scene's display encoding of a linear colour (Shader::toDisplay), in 1/255 steps.
struct Encoder {
    double exposure, inverseGamma;
    float channel(double v) const {
        v = std::clamp(v * exposure, 0.0, 1.0);
        return float(std::round(255 * std::pow(v, inverseGamma)));
    }
};

// Every pixel's samples, one linear colour (straight) and alpha each, sample-major.
struct SampleSet {
    int samples = 0;
    size_t pixels = 0;
    bool opaque = false;
    std::vector<std::vector<Rgba>> linear;   // [k][pixel]
    std::vector<std::vector<uint8_t>> hits;  // [k][pixel]: the sample met the set or the ground

    // The value of pixel p from the samples ks[0..m) as the renderer finishes a pixel
    // (FrameRenderer::finishPixel): straight colour over the covered part, alpha the coverage;
    // opaque samples are already composited, so their mean.
    Display value(size_t p, const int* ks, int m, const Encoder& e) const {
        double covered = 0, sum[3] = {0, 0, 0};
        for (int j = 0; j < m; ++j) {
            const Rgba& s = linear[size_t(ks[j])][p];
            const double a = opaque ? 1.0 : s.a;
            covered += a;
            sum[0] += a * s.r, sum[1] += a * s.g, sum[2] += a * s.b;
        }
        const Rgba& first = linear[size_t(ks[0])][p];  // nothing covered: the background
        Display d;
        for (int c = 0; c < 3; ++c) {
            const double background = c == 0 ? first.r : c == 1 ? first.g : first.b;
            d.c[c] = e.channel(covered > 0 ? sum[c] / covered : background);
        }
        d.c[3] = opaque ? 255.0f : float(std::round(255 * covered / m));
        return d;
    }
    bool hit(size_t p, int k) const { return hits[size_t(k)][p] != 0; }
};

float largestDifference(const Display& a, const Display& b, int channels = 4) {
    float d = 0;
    for (int c = 0; c < channels; ++c)
        d = std::max(d, std::abs(a.c[c] - b.c[c]));
    return d;
}

struct Rule {
    const char* name;
    int first;                      // samples every pixel takes
    float neighbour, edge, second;  // thresholds in 1/255
    bool neighbourColours = true;   // compare colours with the neighbours
};

struct Outcome {
    double extra = 0, all = 0, four = 0, mean = 0, largest = 0;
    long over = 0;
};

// The samples each pixel takes under `rule` and the error of its value against `uniform`.
Outcome simulate(const SampleSet& set, const std::vector<Display>& uniform, int width, int height,
                 const Rule& rule, const int* order, const Encoder& e) {
    const size_t n = set.pixels;
    const int m = rule.first;
    std::vector<Display> first(n);
    std::vector<int> hits(n);
    for (size_t p = 0; p < n; ++p) {
        first[p] = set.value(p, order, m, e);
        for (int j = 0; j < m; ++j)
            hits[p] += set.hit(p, order[j]);
    }
    Outcome o;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t p = size_t(y) * size_t(width) + size_t(x);
            int level = 0;  // 0: the first samples, 1: 4 of them, 2: all
            auto raise = [&](float difference) {
                if (difference > rule.edge)
                    level = 2;
                else if (difference > rule.neighbour)
                    level = std::max(level, 1);
            };
            if (hits[p] > 0 && hits[p] < m) level = 2;
            for (int j = 1; j < m && hits[p] == m; ++j)
                raise(
                    largestDifference(set.value(p, order + j, 1, e), set.value(p, order, 1, e), 3));
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if ((dx == 0 && dy == 0) || qx < 0 || qy < 0 || qx >= width || qy >= height)
                        continue;
                    const size_t q = size_t(qy) * size_t(width) + size_t(qx);
                    if (hits[p] != hits[q])
                        level = 2;
                    else if (hits[p] > 0 && rule.neighbourColours)
                        raise(largestDifference(first[p], first[q], 3));
                }
            }
            int taken = m;
            if (level == 2) {
                taken = set.samples;
            } else if (level == 1) {
                taken = std::max(m, std::min(4, set.samples));
                int h = 0;
                bool disagree = false;
                const Display one = set.value(p, order, 1, e);
                for (int j = 0; j < taken; ++j) {
                    h += set.hit(p, order[j]);
                    if (j > 0 && set.hit(p, order[j]) &&
                        largestDifference(set.value(p, order + j, 1, e), one, 3) > rule.second)
                        disagree = true;
                }
                if (disagree || (h > 0 && h < taken)) taken = set.samples;
            }
            o.all += taken == set.samples;
            o.four += taken > m && taken < set.samples;
            o.extra += taken - m;
            const Display v = set.value(p, order, taken, e);
            for (int c = 0; c < 4; ++c)
                o.mean += std::abs(v.c[c] - uniform[p].c[c]);
            const float d = largestDifference(v, uniform[p]);
            o.largest = std::max(o.largest, double(d));
            o.over += d > 24;
        }
    }
    o.extra /= double(n), o.all /= double(n), o.four /= double(n), o.mean /= 4.0 * double(n);
    return o;
}

double medianSeconds(const Scene& scene, int runs, int64_t* rays) {
    std::vector<double> seconds;
    for (int r = 0; r < runs; ++r) {
        const RenderResult result = render(scene, RenderOptions{});
        seconds.push_back(result.stats.seconds);
        if (rays) *rays = result.stats.rays;
    }
    std::sort(seconds.begin(), seconds.end());
    return seconds[seconds.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    try {
        Scene scene = defaultScene();
        int width = 1920, height = 1080, samples = 16, runs = 3;
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            auto next = [&]() {
                if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
                return std::atoi(argv[++i]);
            };
            if (a == "--width")
                width = next();
            else if (a == "--height")
                height = next();
            else if (a == "--samples")
                samples = next();
            else if (a == "--runs")
                runs = std::max(1, next());
            else
                scene = loadScene(a);
        }
        scene.render.width = width, scene.render.height = height;
        scene.render.samples = samples, scene.render.adaptive = false;
        const Encoder encoder{scene.shading.exposure, 1.0 / scene.shading.gamma};
        const size_t n = size_t(width) * size_t(height);

        RenderOptions options;
        options.passes = true;
        std::vector<Display> uniform(n);
        {
            const RenderResult all = render(scene, options);
            for (size_t p = 0; p < n; ++p) {
                const Rgba& v = all.image.pixels()[p];
                uniform[p] = Display{{float(std::round(255 * v.r)), float(std::round(255 * v.g)),
                                      float(std::round(255 * v.b)), float(std::round(255 * v.a))}};
            }
        }
        SampleSet set{samples, n, scene.render.alpha == AlphaMode::Opaque, {}, {}};
        for (int k = 0; k < samples; ++k) {
            options.onlySample = k;
            RenderResult one = render(scene, options);
            set.hits.emplace_back(one.passes.object.begin(), one.passes.object.end());
            set.linear.push_back(std::move(one.passes.linear));
        }
        const AdaptiveSampling sampling(samples);
        std::vector<int> order(static_cast<size_t>(samples));
        for (int j = 0; j < samples; ++j)
            order[size_t(j)] = sampling.index(j, 0, 0);

        // The samples recombined must give the uniform render (up to rounding).
        float check = 0;
        for (size_t p = 0; p < n; ++p)
            check = std::max(
                check, largestDifference(set.value(p, order.data(), samples, encoder), uniform[p]));
        // The oracle: each pixel's shortest prefix of the order within 24/255.
        std::vector<long> prefix(size_t(samples) + 1, 0);
        double oracleExtra = 0;
        for (size_t p = 0; p < n; ++p) {
            int m = 1;
            while (m < samples &&
                   largestDifference(set.value(p, order.data(), m, encoder), uniform[p]) > 24)
                ++m;
            ++prefix[size_t(m)];
            oracleExtra += m - 1;
        }
        oracleExtra /= double(n);

        // Times: one sample, adaptive and uniform, interleaved.
        Scene one = scene, adaptive = scene;
        one.render.samples = 1;
        adaptive.render.adaptive = true;
        int64_t adaptiveRays = 0;
        const double tOne = medianSeconds(one, runs, nullptr);
        const double tAdaptive = medianSeconds(adaptive, runs, &adaptiveRays);
        const double tUniform = medianSeconds(scene, runs, nullptr);
        const double firstRay = tOne / double(n);
        const double refinedRay = (tAdaptive - tOne) / double(adaptiveRays - int64_t(n));
        const double pass = (tUniform - tOne) / double(samples - 1);

        std::printf(
            "%dx%d, %d samples; recombined samples against the uniform render: largest "
            "difference %.0f/255\n",
            width, height, samples, double(check));
        std::printf(
            "times (medians of %d): one sample %.3f s, adaptive %.3f s (%.2fx, %.2f rays "
            "per pixel), uniform %.3f s (%.2fx)\n",
            runs, tOne, tAdaptive, tAdaptive / tOne, double(adaptiveRays) / double(n), tUniform,
            tUniform / tOne);
        std::printf(
            "a refined sample costs %.2fx a first sample; a further sample of every pixel "
            "%.2fx one sample\n",
            refinedRay / firstRay, pass / tOne);
        std::printf(
            "oracle: %.4f extra samples per pixel (projected %.2fx one sample); pixels by "
            "samples needed:",
            oracleExtra, 1 + oracleExtra * refinedRay / firstRay);
        for (int m = 1; m <= samples; ++m)
            if (prefix[size_t(m)]) std::printf(" %d:%ld", m, prefix[size_t(m)]);
        std::printf("\n\n%-34s %8s %7s %7s %7s %5s %7s %9s\n", "rule", "extra", "all %", "4 %",
                    "mean", "max", "over24", "projected");
        const Rule rules[] = {
            {"product (1 first; 4, 32, 6)", 1, 4, 32, 6},
            {"1 first; 8, 32, 8", 1, 8, 32, 8},
            {"1 first; 16, 48, 8", 1, 16, 48, 8},
            {"1 first; 32, 96, 8", 1, 32, 96, 8},
            {"1 first; silhouettes only", 1, 1e9f, 1e9f, 8, false},
            {"2 first; 4, 32, 6", 2, 4, 32, 6},
            {"2 first; 8, 32, 6", 2, 8, 32, 6},
            {"2 first; 16, 48, 8", 2, 16, 48, 8},
            {"2 first, in-pixel only; 24, 24", 2, 24, 24, 8, false},
            {"2 first, in-pixel only; 8, 32", 2, 8, 32, 8, false},
        };
        for (const Rule& rule : rules) {
            const Outcome o = simulate(set, uniform, width, height, rule, order.data(), encoder);
            const double projected =
                (tOne + (rule.first - 1) * pass) / tOne + o.extra * refinedRay / firstRay;
            std::printf("%-34s %8.4f %7.3f %7.3f %7.4f %5.0f %7ld %8.2fx\n", rule.name, o.extra,
                        100 * o.all, 100 * o.four, o.mean, o.largest, o.over, projected);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quaternia_adaptive_study: %s\n", e.what());
        return 2;
    }
    return 0;
}
