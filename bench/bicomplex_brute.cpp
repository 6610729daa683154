// quaternia_bicomplex_brute: the brute-force silhouette of POV-Ray's hypercomplex (bicomplex)
// julia_fractal, for tests/data/reference/bicomplex: every pixel's ray is sampled with a fixed
// step inside the bounding sphere and each sample tested by iteration; a pixel is white (255)
// when some sample is in the set, black otherwise (8-bit grey PNG, as the quaternion cases'
// brute-force masks).
//
// The set is POV-Ray's (tests/data/reference/bicomplex/ORIGIN.md): the 3D point (x, y, z) is
// the bicomplex number x + y i + z j + w k with w = (d - s^_x x - s^_y y - s^_z z) / s^_w (s^
// the slice normal made unit); z_{n+1} = z_n^power + c; a point escapes when
// x^2 + y^2 + z^2 + w^2 > bailout^2 for one of z_0 .. z_{N-1}. Iterated as two complex numbers
// (the duplex form a = (x - w) + (y + z) i, b = (x + w) + (y - z) i, on which the product acts
// component by component), with |q|^2 = (|a|^2 + |b|^2) / 2. Only the camera comes from the
// library; nothing of Quaternia's set or marcher is used.
//
//   quaternia_bicomplex_brute --c X,Y,Z,W -o OUT.png [--power 2] [--iterations 20]
//       [--bailout 4] [--radius 4] [--slice X,Y,Z,W,D] [--step 0.001] [--width 320]
//       [--height 240] [--camera PX,PY,PZ,LX,LY,LZ] [--fov 45] [--threads 0]
// Exit code 2 with a message on bad input.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bicomplex_brute_mask.h"
#include "quaternia/image/png_writer.h"
#include "quaternia/render/camera.h"

namespace {

struct Options {
    double c[4] = {0, 0, 0, 0};
    bool haveC = false;
    int power = 2;
    int iterations = 20;
    double bailout = 4;  // POV-Ray's hypercomplex: Exit_Value 16
    double radius = 4;   // POV-Ray's hypercomplex bounding sphere
    double slice[5] = {0, 0, 0, 1, 0};
    double step = 0.001;
    int width = 320, height = 240;
    double camera[6] = {1, 1.5, -4, 0, 0, 0};  // location, look_at (sky is +y)
    double fov = 45;
    int threads = 0;
    std::string output;
};

std::vector<double> parseList(const std::string& text, size_t count, const std::string& what) {
    std::vector<double> values;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        size_t used = 0;
        values.push_back(std::stod(item, &used));
        if (used != item.size()) throw std::invalid_argument(what + ": not a number: " + item);
    }
    if (values.size() != count)
        throw std::invalid_argument(what + " takes " + std::to_string(count) + " numbers");
    return values;
}

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string key = argv[i];
        if (i + 1 >= argc) throw std::invalid_argument(key + " needs a value");
        const std::string value = argv[++i];
        auto copy = [&](double* to, size_t n) {
            const auto values = parseList(value, n, key);
            for (size_t k = 0; k < n; ++k)
                to[k] = values[k];
        };
        if (key == "--c") {
            copy(o.c, 4);
            o.haveC = true;
        } else if (key == "--power") {
            o.power = std::stoi(value);
        } else if (key == "--iterations") {
            o.iterations = std::stoi(value);
        } else if (key == "--bailout") {
            o.bailout = std::stod(value);
        } else if (key == "--radius") {
            o.radius = std::stod(value);
        } else if (key == "--slice") {
            copy(o.slice, 5);
        } else if (key == "--step") {
            o.step = std::stod(value);
        } else if (key == "--width") {
            o.width = std::stoi(value);
        } else if (key == "--height") {
            o.height = std::stoi(value);
        } else if (key == "--camera") {
            copy(o.camera, 6);
        } else if (key == "--fov") {
            o.fov = std::stod(value);
        } else if (key == "--threads") {
            o.threads = std::stoi(value);
        } else if (key == "-o") {
            o.output = value;
        } else {
            throw std::invalid_argument("unknown option " + key);
        }
    }
    if (!o.haveC || o.output.empty()) throw std::invalid_argument("--c and -o are required");
    if (o.power < 2 || o.iterations < 1 || !(o.bailout > 0) || !(o.radius > 0) || !(o.step > 0) ||
        o.width < 1 || o.height < 1)
        throw std::invalid_argument(
            "power >= 2, iterations >= 1, positive bailout, radius, "
            "step and size are required");
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace quaternia;
    try {
        const Options o = parseOptions(argc, argv);
        CameraSettings settings;
        settings.position = Point3d(o.camera[0], o.camera[1], o.camera[2]);
        settings.lookAt = Point3d(o.camera[3], o.camera[4], o.camera[5]);
        settings.up = Vector3d(0, 1, 0);
        settings.fovDegrees = o.fov;
        const Camera camera(settings, o.width, o.height);
        bench::BicomplexBrute set;
        std::copy(o.c, o.c + 4, set.c);
        std::copy(o.slice, o.slice + 5, set.slice);
        set.power = o.power, set.iterations = o.iterations, set.bailout = o.bailout;
        set.radius = o.radius, set.step = o.step;

        const auto start = std::chrono::steady_clock::now();
        const std::vector<uint8_t> samples =
            bench::bicomplexBruteMask(set, camera, o.width, o.height, o.threads);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        const PngFormat format{o.width, o.height, 8, PngColorType::Gray};
        const std::vector<uint8_t> png = writePngBytes(format, samples);
        std::ofstream file(o.output, std::ios::binary);
        file.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
        if (!file) throw std::runtime_error("cannot write " + o.output);
        long inside = 0;
        for (uint8_t s : samples)
            inside += s != 0;
        std::printf("%s: %ld pixels inside, %.2f s\n", o.output.c_str(), inside, seconds);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quaternia_bicomplex_brute: %s\n", e.what());
        return 2;
    }
    return 0;
}
