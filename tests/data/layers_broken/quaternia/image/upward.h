// A file that breaks the layering on purpose: scripts/check-layers.py must refuse this tree
// (ctest Layers.ReportsAnIncludeFromALayerAbove).
#pragma once

#include "quaternia/image/image.h"
#include "quaternia/render/lanes/lane_state.h"
