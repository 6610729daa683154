#include "quaternia/mesh/mesh_silhouette.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "quaternia/render/camera.h"

namespace quaternia {

Mask meshSilhouette(const Mesh& mesh, const CameraSettings& settings, int width, int height) {
    Camera camera(settings, width, height);
    std::vector<std::optional<std::array<double, 2>>> image;
    image.reserve(mesh.positions.size());
    for (const Vector3f& p : mesh.positions)
        image.push_back(camera.project(Point3d(p)));
    Mask mask = Mask::blank(width, height);
    for (const Triangle& t : mesh.triangles) {
        if (!image[t[0]] || !image[t[1]] || !image[t[2]]) continue;  // behind the camera
        const auto &a = *image[t[0]], &b = *image[t[1]], &c = *image[t[2]];
        auto edge = [](const std::array<double, 2>& p, const std::array<double, 2>& q, double x,
                       double y) {
            return (q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0]);
        };
        double area = edge(a, b, c[0], c[1]);
        if (area == 0) continue;
        // Pixel (px, py) has its centre at (px + 0.5, py + 0.5), as in Camera::generateRay.
        int x0 = std::max(0, int(std::floor(std::min({a[0], b[0], c[0]}) - 0.5)));
        int x1 = std::min(width - 1, int(std::ceil(std::max({a[0], b[0], c[0]}) - 0.5)));
        int y0 = std::max(0, int(std::floor(std::min({a[1], b[1], c[1]}) - 0.5)));
        int y1 = std::min(height - 1, int(std::ceil(std::max({a[1], b[1], c[1]}) - 0.5)));
        for (int py = y0; py <= y1; ++py)
            for (int px = x0; px <= x1; ++px) {
                double x = px + 0.5, y = py + 0.5;
                // Inside when the three edge functions agree in sign with the whole triangle.
                double e0 = edge(a, b, x, y) * area, e1 = edge(b, c, x, y) * area,
                       e2 = edge(c, a, x, y) * area;
                if (e0 >= 0 && e1 >= 0 && e2 >= 0) mask.set(px, py, true);
            }
    }
    return mask;
}

}  // namespace quaternia
