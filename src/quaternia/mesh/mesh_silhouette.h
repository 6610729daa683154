// A mesh drawn as a silhouette through the renderer's camera, for comparing a mesh with the
// ray-marched picture of the same scene (mask_compare.h): a pixel is inside when its centre
// falls in the projection of some triangle.
#pragma once

#include "quaternia/image/image.h"
#include "quaternia/mesh/mesh.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

Mask meshSilhouette(const Mesh& mesh, const CameraSettings& camera, int width, int height);

}  // namespace quaternia
