// SIMD lanes for the per-pixel work after marching (shade.h): lighting many surface samples at
// once and display encoding, compiled per instruction set by Highway like march_lanes.h and
// chosen at run time. The scalar formulas they mirror are Shader::light and Shader::toDisplay.
#pragma once

#include <cstddef>
#include <vector>

namespace quaternia {

// Display encoding in place of `pixels` RGBA pixels (four floats each, packed): each colour
// channel v becomes min(1, max(0, v * exposure))^inverseGamma, as Shader::toDisplay; alpha is
// kept.
void encodeDisplay(float* rgba, size_t pixels, float exposure, float inverseGamma);

// Shader::light for many surface samples in float lanes: the inputs as structure of arrays, the
// lit colours into red, green and blue. The constants are the Shader's (Shader::lightConstants).
struct LightConstants {
    float fill[3];  // unit direction towards the fill light
    float lightColor[3], fillColor[3];
    float specular, shininess, ambient;
    float highlightCutoff;  // below this cosine the highlight counts as 0
};
struct SurfaceBatch {
    std::vector<float> nx, ny, nz;  // unit normals facing the viewer
    std::vector<float> dx, dy, dz;  // unit view ray directions
    std::vector<float> lx, ly, lz;  // unit directions towards the key light (Shader::keyLight)
    std::vector<float> keyScale;    // the key light's factor (Shader::keyLight)
    std::vector<float> albedoR, albedoG, albedoB, visibility, occlusion;
    std::vector<float> red, green, blue;  // the results
    void resize(size_t n);
    size_t size() const { return nx.size(); }
};
void lightSurfaces(const LightConstants& constants, SurfaceBatch& surfaces);

}  // namespace quaternia
