#include "quaternia/fractal/duplex_escape_map.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

namespace quaternia {
namespace {

using Complex = std::complex<double>;

// Relative rounding allowed per operation on a magnitude (a few ulps, generously).
constexpr double kRelative = 0x1p-50;
// Cells are certified as discs this much wider (absolute), so that a point whose duplex
// component is computed with rounding (a few ulps of at most sqrt(2) B) into a cell lies in the
// disc certified for it.
constexpr double kCellMargin = 1e-12;

// The squared distance transform of one line (Felzenszwalb and Huttenlocher, "Distance
// transforms of sampled functions", Theory of Computing 8, 2012): out[q] = min_p (q - p)^2 +
// f[p], with the lower envelope of the parabolas rooted at each p.
void distanceTransform(const float* f, float* out, int64_t n, int64_t stride,
                       std::vector<int64_t>& v, std::vector<float>& z) {
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    v.resize(size_t(n));
    z.resize(size_t(n + 1));
    int64_t k = -1;
    for (int64_t q = 0; q < n; ++q) {
        const float fq = f[q * stride];
        if (!(fq < kInfinity)) continue;
        while (k >= 0) {
            const int64_t p = v[size_t(k)];
            const float s =
                ((fq + float(q * q)) - (f[p * stride] + float(p * p))) / float(2 * (q - p));
            if (s > z[size_t(k)]) {
                v[size_t(++k)] = q;
                z[size_t(k)] = s;
                z[size_t(k + 1)] = kInfinity;
                break;
            }
            --k;
        }
        if (k < 0) {
            k = 0;
            v[0] = q;
            z[0] = -kInfinity;
            z[1] = kInfinity;
        }
    }
    if (k < 0) {
        for (int64_t q = 0; q < n; ++q)
            out[q * stride] = kInfinity;
        return;
    }
    int64_t j = 0;
    for (int64_t q = 0; q < n; ++q) {
        while (z[size_t(j + 1)] < float(q))
            ++j;
        const int64_t p = v[size_t(j)];
        out[q * stride] = float((q - p) * (q - p)) + f[p * stride];
    }
}

}  // namespace

DuplexEscapeMap::DuplexEscapeMap(const DuplexComponentProgram& program, int maxIterations,
                                 double bailout, int finestLevel)
    : maxIterations_(maxIterations),
      half_(std::sqrt(2.0) * bailout),
      finestLevel_(finestLevel),
      cells_(int64_t(1) << finestLevel),
      cellSize_(std::ldexp(2 * half_, -finestLevel)) {
    outside_.assign(size_t(cells_ * cells_), 0);
    Certifying with{program, {}};
    certify(with, 0, 0, 0);
    computeClearance();
}

DuplexEscapeMap::Verdict DuplexEscapeMap::iterate(Certifying& with, ComplexDisc w) const {
    double reach = 0;
    for (int n = 0;; ++n) {
        const double magnitude = std::sqrt(std::norm(w.centre));
        if (magnitude * (1 - kRelative) - w.radius > half_) return Verdict::kOutside;
        const double upper = (magnitude + w.radius) * (1 + kRelative);
        if (!std::isfinite(upper)) return Verdict::kUndecided;
        reach = std::max(reach, upper);
        if (n + 1 >= maxIterations_) break;
        w = with.program.disc(w, with.registers);
    }
    return reach <= half_ ? Verdict::kBounded : Verdict::kUndecided;
}

void DuplexEscapeMap::certify(Certifying& with, int level, int64_t x, int64_t y) {
    const double size = std::ldexp(2 * half_, -level);
    const ComplexDisc cell{
        Complex(-half_ + (double(x) + 0.5) * size, -half_ + (double(y) + 0.5) * size),
        size * std::sqrt(0.5) * (1 + kRelative) + kCellMargin};
    switch (iterate(with, cell)) {
        case Verdict::kOutside: {
            const int shift = finestLevel_ - level;
            const int64_t side = int64_t(1) << shift;
            for (int64_t j = 0; j < side; ++j)
                std::fill_n(outside_.begin() + ((y << shift) + j) * cells_ + (x << shift), side,
                            uint16_t(1));
            return;
        }
        case Verdict::kBounded:
            return;  // every orbit of the cell stays within sqrt(2) B: no outside cell below
        case Verdict::kUndecided:
            break;
    }
    if (level == finestLevel_) return;
    for (int64_t dy = 0; dy < 2; ++dy)
        for (int64_t dx = 0; dx < 2; ++dx)
            certify(with, level + 1, 2 * x + dx, 2 * y + dy);
}

void DuplexEscapeMap::computeClearance() {
    // Squared distances in cells from each cell's centre to the nearest centre of a cell that is
    // not outside (rows, then columns as the rows of the transpose: a strided pass misses the
    // cache).
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    std::vector<float> f(outside_.size()), rows(outside_.size());
    for (size_t k = 0; k < f.size(); ++k)
        f[k] = outside_[k] ? kInfinity : 0.0f;
    auto transpose = [&](const std::vector<float>& from, std::vector<float>& to) {
        constexpr int64_t kBlock = 64;
        for (int64_t y0 = 0; y0 < cells_; y0 += kBlock)
            for (int64_t x0 = 0; x0 < cells_; x0 += kBlock)
                for (int64_t y = y0; y < std::min(y0 + kBlock, cells_); ++y)
                    for (int64_t x = x0; x < std::min(x0 + kBlock, cells_); ++x)
                        to[size_t(x * cells_ + y)] = from[size_t(y * cells_ + x)];
    };
    std::vector<int64_t> v;
    std::vector<float> z;
    for (int64_t y = 0; y < cells_; ++y)
        distanceTransform(&f[size_t(y * cells_)], &rows[size_t(y * cells_)], cells_, 1, v, z);
    transpose(rows, f);
    for (int64_t x = 0; x < cells_; ++x)
        distanceTransform(&f[size_t(x * cells_)], &rows[size_t(x * cells_)], cells_, 1, v, z);
    transpose(rows, f);
    for (size_t k = 0; k < f.size(); ++k) {
        if (!outside_[k]) continue;
        // From the centre to the nearest such cell: at least sqrt(D) less half a diagonal, kept
        // in quarters of a cell rounded down, after the 1 that marks the cell outside. Where no
        // cell is anything but outside (E_i empty), D is infinite: the largest code.
        const double quarters = 4 * (std::sqrt(double(f[k])) - std::sqrt(0.5)) - 1e-3;
        outside_[k] = uint16_t(1 + std::clamp(std::floor(quarters), 0.0, 65534.0));
    }
}

int64_t DuplexEscapeMap::cellOf(Complex w) const {
    const double x = (w.real() + half_) / cellSize_, y = (w.imag() + half_) / cellSize_;
    if (!(x >= 0 && y >= 0 && x <= double(cells_) && y <= double(cells_))) return -1;
    const int64_t ix = std::min(int64_t(x), cells_ - 1), iy = std::min(int64_t(y), cells_ - 1);
    return iy * cells_ + ix;
}

double DuplexEscapeMap::clearance(Complex w) const {
    const int64_t cell = cellOf(w);
    if (cell >= 0) {
        // The centre's clearance less w's distance from the centre.
        const int quarters = int(outside_[size_t(cell)]) - 1;
        if (quarters <= 0) return 0;
        const double x = w.real() + half_ - (double(cell % cells_) + 0.5) * cellSize_,
                     y = w.imag() + half_ - (double(cell / cells_) + 0.5) * cellSize_;
        return std::max(0.0, 0.25 * quarters * cellSize_ * (1 - 1e-9) -
                                 std::sqrt(x * x + y * y) * (1 + kRelative) - 1e-12);
    }
    // Beyond the square, every point of E_i lies in it: with w' the nearest point of the square
    // (convex), |w - y|^2 >= |w - w'|^2 + |w' - y|^2 for each y in it.
    if (!std::isfinite(std::norm(w))) return 0;
    const Complex nearest(std::clamp(w.real(), -half_, half_), std::clamp(w.imag(), -half_, half_));
    const double beyond = std::abs(w - nearest) * (1 - kRelative);
    const double inside = clearance(nearest);
    return std::sqrt(beyond * beyond + inside * inside);
}

bool DuplexEscapeMap::outside(Complex w) const {
    const int64_t cell = cellOf(w);
    return cell < 0 ? std::isfinite(std::norm(w)) : outside_[size_t(cell)] > 0;
}

namespace {
constexpr size_t kCachedMaps = 4;  // at most 8 MB each at the default level
}  // namespace

uint64_t DuplexEscapeMap::peakBytes(int finestLevel) {
    const uint64_t cells = uint64_t(1) << (2 * finestLevel);
    const uint64_t building = cells * (sizeof(uint16_t) + 2 * sizeof(float));
    return 2 * building + (kCachedMaps - 2) * cells * sizeof(uint16_t);
}

std::shared_ptr<const DuplexEscapeMap> DuplexEscapeMap::shared(
    const DuplexComponentProgram& program, int maxIterations, double bailout, int finestLevel) {
    struct Entry {
        std::vector<double> key;
        std::shared_ptr<const DuplexEscapeMap> map;
    };
    static std::mutex mutex;
    static std::vector<Entry> cache;  // the most recently used first
    std::vector<double> key = program.signature();
    key.insert(key.end(), {double(maxIterations), bailout, double(finestLevel)});
    {
        const std::lock_guard<std::mutex> lock(mutex);
        for (size_t k = 0; k < cache.size(); ++k) {
            if (cache[k].key != key) continue;
            std::rotate(cache.begin(), cache.begin() + std::ptrdiff_t(k),
                        cache.begin() + std::ptrdiff_t(k) + 1);
            return cache.front().map;
        }
    }
    // Built outside the lock (a second thread asking for the same map builds it too: the same
    // map, deterministic).
    auto map =
        std::make_shared<const DuplexEscapeMap>(program, maxIterations, bailout, finestLevel);
    const std::lock_guard<std::mutex> lock(mutex);
    cache.insert(cache.begin(), Entry{std::move(key), map});
    if (cache.size() > kCachedMaps) cache.pop_back();
    return map;
}

DuplexEscapeMaps::DuplexEscapeMaps(const std::array<DuplexComponentProgram, 2>& programs,
                                   int maxIterations, double bailout, int finestLevel) {
    if (programs[0].signature() == programs[1].signature()) {
        maps_[0] = maps_[1] =
            DuplexEscapeMap::shared(programs[0], maxIterations, bailout, finestLevel);
        return;
    }
    // The two planes on two threads (the caller's render threads wait for the maps).
    std::exception_ptr failed;
    std::thread second([&] {
        try {
            maps_[1] = DuplexEscapeMap::shared(programs[1], maxIterations, bailout, finestLevel);
        } catch (...) {
            failed = std::current_exception();
        }
    });
    try {
        maps_[0] = DuplexEscapeMap::shared(programs[0], maxIterations, bailout, finestLevel);
    } catch (...) {
        second.join();
        throw;
    }
    second.join();
    if (failed) std::rethrow_exception(failed);
}

double DuplexEscapeMaps::clearance(const Hypercomplex& q) const {
    const auto w = duplexForm(q);
    const double a = maps_[0]->clearance(w[0]), b = maps_[1]->clearance(w[1]);
    // |q - y| = |(a - a', b - b')| / sqrt(2).
    return std::sqrt(0.5 * (a * a + b * b)) * (1 - 1e-9);
}

bool DuplexEscapeMaps::outside(const Hypercomplex& q) const {
    const auto w = duplexForm(q);
    return maps_[0]->outside(w[0]) || maps_[1]->outside(w[1]);
}

}  // namespace quaternia
