// A camera-free 2D view of a plane (the complex plane, the parameter plane, or a plane through
// H): the point at the image centre, the width of the view in plane units, a rotation, and the
// image size. Row 0 is the top; the plane's second axis points up.
#pragma once

#include <cmath>
#include <complex>
#include <numbers>

namespace quaternia {

struct PlaneView {
    std::complex<double> centre{0, 0};
    double width = 4;            // plane units across the image
    double rotationDegrees = 0;  // counter-clockwise turn of the view about its centre
    int pixelWidth = 0, pixelHeight = 0;

    // The plane point at image position (x, y) in pixels; (px + 0.5, py + 0.5) is the centre
    // of pixel (px, py).
    std::complex<double> pointAt(double x, double y) const {
        double scale = width / pixelWidth;
        std::complex<double> offset((x - 0.5 * pixelWidth) * scale,
                                    (0.5 * pixelHeight - y) * scale);
        return centre + offset * std::polar(1.0, rotationDegrees * std::numbers::pi / 180);
    }
    double pixelSize() const { return width / pixelWidth; }
};

}  // namespace quaternia
