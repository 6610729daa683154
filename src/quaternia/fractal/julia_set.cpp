#include "quaternia/fractal/julia_set.h"

#include <cmath>

#include "quaternia/interval/ball_form.h"
#include "quaternia/interval/interval_element.h"

namespace quaternia {

std::optional<std::string> JuliaSet::unprovablePart() const {
    return withoutIntervalExtension(program());
}

bool JuliaSet::excludesSegment(const Hypercomplex& from, const Hypercomplex& to,
                               double thickness) const {
    if (!hasIntervalExtension()) return false;
    const MultiplicationTable& table = MultiplicationTable::of(algebra());
    return segmentLeavesBall(program(), table,
                             segmentBetween(from, to, thickness, table.dimension()),
                             maxIterations(), bailout());
}

bool JuliaSet::excludesTube(const TubeForm& tube) const {
    if (!hasIntervalExtension()) return false;
    return tubeLeavesBall(program(), MultiplicationTable::of(algebra()), tube, maxIterations(),
                          bailout());
}

bool JuliaSet::includesBox(const Hypercomplex& centre, double radius) const {
    if (!hasIntervalExtension()) return false;
    const MultiplicationTable& table = MultiplicationTable::of(algebra());
    // The ball about the box first (ball_form.h), then the box.
    const double ball = std::sqrt(double(table.dimension())) * radius * (1 + 1e-15);
    return ballStaysInBall(program(), table, {centre, ball}, maxIterations(), bailout()) ||
           boxAboutStaysInBall(program(), table, centre, radius, maxIterations(), bailout());
}

}  // namespace quaternia
