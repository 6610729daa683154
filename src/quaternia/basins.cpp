// Placeholder until the dynamics work lands: the interface is fixed in basins.h so that the
// `plane` command can be written against it in parallel.
#include "basins.h"

#include <stdexcept>

namespace quaternia {

BasinImage renderBasins(const ComplexPolynomial&, const PlaneView&, const BasinOptions&) {
    throw std::logic_error("renderBasins: not implemented yet");
}

}  // namespace quaternia
