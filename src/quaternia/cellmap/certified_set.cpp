#include "quaternia/cellmap/certified_set.h"

#include <zlib.h>

#include <cstring>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include "quaternia/cellmap/byte_record.h"

#include "quaternia/util/error.h"

namespace quaternia {
namespace {

constexpr char kMagic[] = "QUATERNIA-CELLS 1\n";
constexpr size_t kMagicLength = sizeof(kMagic) - 1;
// A decoded set larger than this is refused (a damaged or hostile size field).
constexpr uint64_t kMaxDecodedBytes = uint64_t(8) << 30;

Interval pointInterval(double x) {
    return Interval::point(x);
}

}  // namespace

// x = Re z, a = <Im z, n>, r = |Im z - a n| (certified_set.h), enclosed componentwise.
std::array<Interval, 3> CertifiedSet::reducedBox(const Interval* box, int dimension) const {
    Interval a = pointInterval(0);
    for (int k = 1; k < dimension; ++k)
        if (axis[k] != 0) a = a + axis[k] * box[k];
    Interval rSquared = pointInterval(0);
    for (int k = 1; k < dimension; ++k)
        rSquared = rSquared + square(box[k] - axis[k] * a);
    const Interval r{std::max(0.0, roundedDown(std::sqrt(std::max(0.0, rSquared.lo)))),
                     roundedUp(std::sqrt(std::max(0.0, rSquared.hi)))};
    return {box[0], a, r};
}

CellClass CertifiedSet::classOfBox(const Interval* box, int dimension) const {
    if (space == CertifiedSpace::kProduct) {
        // duplexForm: ((z0 - z3) + (z1 + z2) i, (z0 + z3) + (z1 - z2) i)
        const std::array<Interval, 3> first{box[0] - box[3], box[1] + box[2], {}};
        const std::array<Interval, 3> second{box[0] + box[3], box[1] - box[2], {}};
        const CellClass a = grids[0].classOfBox(first, true);
        if (a == CellClass::kOutside) return a;
        const CellClass b = grids[1].classOfBox(second, true);
        if (b == CellClass::kOutside) return b;
        return a == CellClass::kInside && b == CellClass::kInside ? CellClass::kInside
                                                                  : CellClass::kUndecided;
    }
    return grids[0].classOfBox(reducedBox(box, dimension), true);
}

uint8_t CertifiedSet::classesOfBox(const Interval* box, int dimension) const {
    if (space == CertifiedSpace::kProduct) {
        const uint8_t a = grids[0].classesInBox({box[0] - box[3], box[1] + box[2], {}}, true);
        const uint8_t b = grids[1].classesInBox({box[0] + box[3], box[1] - box[2], {}}, true);
        if (a == CellGrid::kHasOutside || b == CellGrid::kHasOutside) return CellGrid::kHasOutside;
        if (a == CellGrid::kHasInside && b == CellGrid::kHasInside) return CellGrid::kHasInside;
        return uint8_t(CellGrid::kHasUndecided | CellGrid::kHasOutside |
                       ((a & b & CellGrid::kHasInside) ? CellGrid::kHasInside : 0));
    }
    return grids[0].classesInBox(reducedBox(box, dimension), true);
}

CellClass CertifiedSet::classOfPoint(const Hypercomplex& z, int dimension) const {
    Interval box[kMaxAlgebraDimension];
    for (int k = 0; k < dimension; ++k)
        box[k] = pointInterval(z[k]);
    return classOfBox(box, dimension);
}

std::vector<uint8_t> CertifiedSet::encode() const {
    std::vector<uint8_t> body;
    appendValue<uint8_t>(body, uint8_t(space));
    appendValue<uint8_t>(body, uint8_t(algebra));
    appendValue<uint32_t>(body, uint32_t(formula.size()));
    for (char ch : formula)
        appendValue<char>(body, ch);
    for (int k = 0; k < kMaxAlgebraDimension; ++k)
        appendValue<double>(body, c[k]);
    for (int k = 0; k < kMaxAlgebraDimension; ++k)
        appendValue<double>(body, axis[k]);
    appendValue<double>(body, realConstant);
    appendValue<double>(body, imaginaryConstant);
    appendValue<double>(body, escapeRadius);
    appendValue<uint32_t>(body, uint32_t(coefficients.size()));
    for (double a : coefficients)
        appendValue<double>(body, a);
    appendValue<uint32_t>(body, uint32_t(grids.size()));
    for (const CellGrid& grid : grids)
        grid.appendTo(body);

    uLongf packedSize = compressBound(uLong(body.size()));
    std::vector<uint8_t> out(kMagic, kMagic + kMagicLength);
    appendValue<uint64_t>(out, body.size());
    const size_t at = out.size();
    out.resize(at + packedSize);
    if (compress2(out.data() + at, &packedSize, body.data(), uLong(body.size()), 6) != Z_OK)
        throw std::runtime_error("zlib compress2 failed");
    out.resize(at + packedSize);
    return out;
}

CertifiedSet CertifiedSet::decode(const std::vector<uint8_t>& bytes, const std::string& key,
                                  const std::string& name) {
    auto bad = [&](const std::string& why) {
        return UserError(key, key + ": " + (name.empty() ? "" : name + " is ") +
                                  "not a certified set written by `quaternia certify` (" + why +
                                  ")");
    };
    if (bytes.size() < kMagicLength + 8 || std::memcmp(bytes.data(), kMagic, kMagicLength) != 0)
        throw bad("no QUATERNIA-CELLS header");
    uint64_t size;
    std::memcpy(&size, bytes.data() + kMagicLength, 8);
    if (size > kMaxDecodedBytes) throw bad("size field out of range");
    std::vector<uint8_t> body(static_cast<size_t>(size));
    uLongf bodySize = uLongf(size);
    const size_t at = kMagicLength + 8;
    if (uncompress(body.data(), &bodySize, bytes.data() + at, uLong(bytes.size() - at)) != Z_OK ||
        bodySize != size)
        throw bad("damaged compressed data");
    CertifiedSet set;
    try {
        const uint8_t* p = body.data();
        const uint8_t* end = p + body.size();
        const uint8_t space = takeValue<uint8_t>(p, end), algebra = takeValue<uint8_t>(p, end);
        if (space != uint8_t(CertifiedSpace::kReduced) &&
            space != uint8_t(CertifiedSpace::kProduct))
            throw std::runtime_error("unknown space");
        if (algebra > uint8_t(Algebra::kOctonion)) throw std::runtime_error("unknown algebra");
        set.space = CertifiedSpace(space);
        set.algebra = Algebra(algebra);
        const uint32_t length = takeValue<uint32_t>(p, end);
        if (length > uint32_t(end - p)) throw std::runtime_error("truncated");
        set.formula.assign(reinterpret_cast<const char*>(p), length);
        p += length;
        for (int k = 0; k < kMaxAlgebraDimension; ++k)
            set.c[k] = takeValue<double>(p, end);
        for (int k = 0; k < kMaxAlgebraDimension; ++k)
            set.axis[k] = takeValue<double>(p, end);
        set.realConstant = takeValue<double>(p, end);
        set.imaginaryConstant = takeValue<double>(p, end);
        set.escapeRadius = takeValue<double>(p, end);
        const uint32_t count = takeValue<uint32_t>(p, end);
        if (count > 64) throw std::runtime_error("too many coefficients");
        for (uint32_t n = 0; n < count; ++n)
            set.coefficients.push_back(takeValue<double>(p, end));
        const uint32_t grids = takeValue<uint32_t>(p, end);
        const uint32_t expected = set.space == CertifiedSpace::kReduced ? 1 : 2;
        const int dimension = set.space == CertifiedSpace::kReduced ? 3 : 2;
        if (grids != expected) throw std::runtime_error("wrong number of grids");
        for (uint32_t n = 0; n < grids; ++n) {
            set.grids.push_back(CellGrid::readFrom(p, end));
            if (set.grids.back().dimension() != dimension) throw std::runtime_error("wrong grid");
        }
        if (p != end) throw std::runtime_error("trailing bytes");
    } catch (const std::runtime_error& error) {
        throw bad(error.what());
    }
    return set;
}

CertifiedSet CertifiedSet::read(const std::string& path, const std::string& key) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw UserError(key, key + ": cannot read " + path);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
    return decode(bytes, key, path);
}

}  // namespace quaternia
