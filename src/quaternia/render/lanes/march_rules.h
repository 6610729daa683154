// Rules of the march that the scalar marcher (render/march.h) and the lanes
// (march_lanes-inl.h) share. They live here, below both, so that the lanes need not include the
// scalar marcher.
#pragma once

namespace quaternia {

// Sphere tracing's membership confirmation (sphereTrace): once the estimate is below epsilon,
// steps of at least this many pixel footprints, for at most this many steps. Against the
// brute-force masks of the reference cases (fixed steps of about a tenth of a footprint there),
// a fifth draws the closest silhouettes: a twentieth or a tenth end more grazing rays on the
// offset surface when the budget runs out (case01 IoU 0.9969, 0.9972 against 0.9980; 20% and
// 11% more steps), three tenths begin to miss thin parts the masks have.
inline constexpr double kMarchConfirmStep = 0.2;
inline constexpr int kMarchConfirmBudget = 48;

}  // namespace quaternia
