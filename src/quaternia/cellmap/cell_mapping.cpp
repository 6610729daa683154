#include "quaternia/cellmap/cell_mapping.h"

#include <algorithm>
#include <atomic>
#include <chrono>

#include "quaternia/util/error.h"
#include "quaternia/util/memory_budget.h"

namespace quaternia {
namespace {

// The value of a cell that is still a candidate for the inside (the greatest fixed point).
constexpr uint8_t kCandidate = 200;
// Levels with at most this many undecided cells, and every level until an inside cell is
// found, look for trapped regions from scratch (the greatest fixed point); the others grow the
// inside they inherit.
constexpr size_t kGreatestFixedPointCells = size_t(1) << 18;

// Cells of a level as one 64-bit key: 21 bits per axis (2^21 cells per axis at most).
using CellKey = uint64_t;
constexpr int kKeyBits = 21;
constexpr int64_t kMaxCellsPerAxis = int64_t(1) << kKeyBits;

CellKey keyOf(const CellIndex& c) {
    return uint64_t(c[0]) | uint64_t(c[1]) << kKeyBits | uint64_t(c[2]) << 2 * kKeyBits;
}
CellIndex indexOf(CellKey k) {
    const uint64_t mask = (uint64_t(1) << kKeyBits) - 1;
    return {int64_t(k & mask), int64_t((k >> kKeyBits) & mask), int64_t(k >> 2 * kKeyBits)};
}

Box3 cellBox(const CellGrid& grid, int level, const CellIndex& c) {
    Box3 box{};
    for (int a = 0; a < grid.dimension(); ++a)
        box[a] = {grid.cellLower(level, a, c[a]), grid.cellLower(level, a, c[a] + 1)};
    return box;
}

// A cell's image at its level, computed once per level: the cells it touches, and whether the
// cell lies beyond the escape radius or its image leaves the grid.
struct Image {
    std::array<int32_t, 3> first{0, 0, 0};
    std::array<uint8_t, 3> extent{0, 0, 0};  // last - first per axis
    uint8_t flags = 0;
    static constexpr uint8_t kEscapes = 1;  // every point of the cell escapes
    static constexpr uint8_t kBeyond = 2;   // part of the image lies beyond the grid (and R)
    static constexpr uint8_t kEmpty = 4;    // the whole image lies beyond the grid
    static constexpr uint8_t kWide = 8;     // wider than 256 cells: nothing is decided from it
    bool has(uint8_t flag) const { return (flags & flag) != 0; }
};

// The cell's image under f (iterates 1) or f^k (BoxMap::iterateImage). f^k's images are kept
// where they are at most kIterateExtent cells across (where f stretches little: what they are
// for); wider ones are marked wide and never read, which saves the long scans of their
// successes.
constexpr int64_t kIterateExtent = 8;

Image imageOf(const CellGrid& grid, const BoxMap& map, int level, const CellIndex& c,
              int iterates = 1) {
    Image image;
    const Box3 box = cellBox(grid, level, c);
    if (map.escapes(box)) {
        image.flags = Image::kEscapes;
        return image;
    }
    const Box3 mapped = iterates == 1 ? map.image(box) : map.iterateImage(box, iterates);
    for (int a = 0; a < grid.dimension(); ++a) {
        const AxisRange r = grid.cellsTouched(level, a, mapped[a]);
        if (r.beyond) image.flags |= Image::kBeyond;
        if (r.first > r.last) {
            image.flags |= Image::kEmpty;
            continue;
        }
        if (r.last - r.first > (iterates == 1 ? 255 : kIterateExtent)) image.flags |= Image::kWide;
        image.first[size_t(a)] = int32_t(r.first);
        image.extent[size_t(a)] = uint8_t(std::min<int64_t>(255, r.last - r.first));
    }
    return image;
}

template <typename Visit>
bool visitImage(const CellGrid& grid, int level, const Image& image, Visit&& visit) {
    return grid.visitCells(level, {image.first[0], image.first[1], image.first[2]},
                           {image.first[0] + image.extent[0], image.first[1] + image.extent[1],
                            image.first[2] + image.extent[2]},
                           visit);
}

bool cancelled(const WorkOptions& work) {
    return work.cancel && work.cancel->load(std::memory_order_relaxed);
}

// Sweeps the cells numbered `active` until a sweep changes none: test(n) returns true where
// cell n moved to its new value (it wrote it). Cells that moved leave the list. Returns the
// sweep count, or -1 if cancelled.
template <typename Test>
int sweepToFixedPoint(std::vector<int32_t>& active, const WorkOptions& work, Test&& test) {
    int sweeps = 0;
    std::vector<uint8_t> moved;
    while (!active.empty()) {
        if (cancelled(work)) return -1;
        ++sweeps;
        moved.assign(active.size(), 0);
        std::atomic<int64_t> changes{0};
        ParallelOptions parallel;
        parallel.threads = work.threads;
        parallel.chunkSize = 4096;
        parallelFor(int64_t(active.size()), parallel, [&](int64_t begin, int64_t end, int) {
            int64_t local = 0;
            for (int64_t n = begin; n < end; ++n)
                if (test(size_t(active[size_t(n)]))) moved[size_t(n)] = 1, ++local;
            changes += local;
        });
        if (changes.load() == 0) break;
        size_t kept = 0;
        for (size_t n = 0; n < active.size(); ++n)
            if (!moved[n]) active[kept++] = active[n];
        active.resize(kept);
    }
    return sweeps;
}

// The least fixed point of "every cell the image touches has value `target`" over the cells
// whose state is kPending, worklist style: a cell that a touched cell blocks waits on that
// cell's list if the blocker may still reach `target` (a pending cell of this level), and is
// tested again only when it does; blocked by anything else, it is done. Every cell is tested
// about once per blocker that falls, instead of once per sweep. Sets the cells that reach
// `target` (grid and state kReached).
enum : uint8_t { kPending = 0, kReached = 1, kExcluded = 2 };

int64_t growToFixedPoint(CellGrid& grid, int level, const std::vector<CellKey>& cells,
                         const std::vector<const std::vector<Image>*>& sets,
                         std::vector<uint8_t>& state, const std::vector<int32_t>& slots,
                         uint8_t target, bool outsideRules, const WorkOptions& work) {
    const size_t count = cells.size(), setCount = sets.size();
    // Per image set: the wait lists (head per blocker, next per waiting cell) and whether a
    // cell waits in that set's list (then its blocker has not moved, and the set is not tried).
    std::vector<std::vector<int32_t>> waitHead(setCount, std::vector<int32_t>(count, -1));
    std::vector<std::vector<int32_t>> waitNext(setCount, std::vector<int32_t>(count, -1));
    std::vector<std::vector<uint8_t>> waiting(setCount, std::vector<uint8_t>(count, 0));
    std::vector<int32_t> queue;
    queue.reserve(count);
    for (size_t n = count; n-- > 0;)
        if (state[n] == kPending) queue.push_back(int32_t(n));
    int64_t reached = 0, tests = 0;
    while (!queue.empty()) {
        if ((++tests & 0xFFFF) == 0 && cancelled(work)) return -1;
        const int32_t n = queue.back();
        queue.pop_back();
        if (state[size_t(n)] != kPending) continue;
        bool ok = false;
        for (size_t s = 0; s < setCount && !ok; ++s) {
            if (waiting[s][size_t(n)]) continue;
            const Image& image = (*sets[s])[size_t(n)];
            int32_t blocker = -1;
            if (outsideRules && (image.has(Image::kEscapes) || image.has(Image::kEmpty))) {
                ok = true;
            } else if (image.has(Image::kWide) || (!outsideRules && image.has(Image::kBeyond))) {
                ok = false;
            } else {
                ok = visitImage(grid, level, image, [&](const CellIndex& touched, uint8_t v) {
                    if (v == target) return true;
                    const int64_t slot = grid.cellSlot(level, touched);
                    const int32_t b = slot >= 0 ? slots[size_t(slot)] : -1;
                    if (b >= 0 && state[size_t(b)] == kPending) blocker = b;
                    return false;
                });
            }
            if (!ok && blocker >= 0) {
                waitNext[s][size_t(n)] = waitHead[s][size_t(blocker)];
                waitHead[s][size_t(blocker)] = n;
                waiting[s][size_t(n)] = 1;
            }
        }
        if (!ok) continue;
        __atomic_store_n(grid.valueAddress(level, indexOf(cells[size_t(n)])), target,
                         __ATOMIC_RELAXED);
        state[size_t(n)] = kReached;
        ++reached;
        for (size_t s = 0; s < setCount; ++s) {
            for (int32_t w = waitHead[s][size_t(n)]; w >= 0;) {
                const int32_t next = waitNext[s][size_t(w)];
                waiting[s][size_t(w)] = 0;
                queue.push_back(w);
                w = next;
            }
            waitHead[s][size_t(n)] = -1;
        }
    }
    return reached;
}

}  // namespace

CellMappingReport classifyCells(CellGrid& grid, const BoxMap& map,
                                const CellMappingOptions& options) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    CellMappingReport report;
    const int dimension = grid.dimension();
    for (int a = 0; a < dimension; ++a)
        if (grid.cellsAt(options.finestLevel, a) > kMaxCellsPerAxis)
            throw UserError(options.memoryKey,
                            "the finest cells would number more than 2^21 along an axis");

    // Level 0's undecided cells.
    std::vector<CellKey> undecided;
    for (int64_t k = 0; k < (dimension > 2 ? grid.cellsAt(0, 2) : 1); ++k)
        for (int64_t j = 0; j < grid.cellsAt(0, 1); ++j)
            for (int64_t i = 0; i < grid.cellsAt(0, 0); ++i)
                if (grid.valueAt(0, {i, j, k}) == uint8_t(CellClass::kUndecided))
                    undecided.push_back(keyOf({i, j, k}));

    bool foundInside = false;
    for (int level = 0;; ++level) {
        const auto levelStart = Clock::now();
        CellMappingLevel stats;
        stats.level = level;
        stats.cells = int64_t(undecided.size());
        auto store = [&](const CellIndex& c, uint8_t value) {
            __atomic_store_n(grid.valueAddress(level, c), value, __ATOMIC_RELAXED);
        };

        // Every cell's image, once.
        std::vector<Image> images(undecided.size());
        {
            ParallelOptions parallel;
            parallel.threads = options.work.threads;
            parallel.chunkSize = 4096;
            parallelFor(int64_t(undecided.size()), parallel, [&](int64_t begin, int64_t end, int) {
                for (int64_t n = begin; n < end; ++n)
                    images[size_t(n)] = imageOf(grid, map, level, indexOf(undecided[size_t(n)]));
            });
        }

        // f^k's images too (BoxMap::iterateImage): a cell is decided by whichever set proves it.
        std::vector<std::vector<Image>> iterated;
        for (int k : map.iterateImage ? map.iterates : std::vector<int>{}) {
            std::vector<Image>& set = iterated.emplace_back(undecided.size());
            ParallelOptions parallel;
            parallel.threads = options.work.threads;
            parallel.chunkSize = 4096;
            parallelFor(int64_t(undecided.size()), parallel, [&](int64_t begin, int64_t end, int) {
                for (int64_t n = begin; n < end; ++n)
                    set[size_t(n)] = imageOf(grid, map, level, indexOf(undecided[size_t(n)]), k);
            });
        }
        std::vector<const std::vector<Image>*> sets{&images};
        for (const std::vector<Image>& set : iterated)
            sets.push_back(&set);

        // Each cell's place in `undecided`, by its slot in the grid's tiles.
        std::vector<int32_t> slots(size_t(grid.slotCount(level)), -1);
        for (size_t n = 0; n < undecided.size(); ++n)
            slots[size_t(grid.cellSlot(level, indexOf(undecided[n])))] = int32_t(n);
        std::vector<uint8_t> state(undecided.size(), kPending);

        // Outside: the least fixed point (header comment).
        const auto outsideValue = uint8_t(CellClass::kOutside);
        if (growToFixedPoint(grid, level, undecided, sets, state, slots, outsideValue, true,
                             options.work) < 0)
            break;
        // The cells left, by number.
        std::vector<int32_t> active;
        for (size_t n = 0; n < undecided.size(); ++n) {
            if (state[n] == kReached) {
                state[n] = kExcluded;  // outside: never inside
                continue;
            }
            active.push_back(int32_t(n));
        }
        stats.outside = stats.cells - int64_t(active.size());

        // Inside. Where the level has few cells or no inside was found yet, the greatest fixed
        // point over the cells left, all candidates at first: it finds every trapped region.
        // Beyond that, the least fixed point grown from the inside cells of the levels above
        // (as the outside grows from the escape region), which tests each cell about once per
        // blocker instead of once per sweep.
        const auto insideValue = uint8_t(CellClass::kInside);
        const bool greatest = active.size() <= kGreatestFixedPointCells || !foundInside;
        if (greatest) {
            std::vector<int32_t> candidates = active;
            for (int32_t n : active)
                store(indexOf(undecided[size_t(n)]), kCandidate);
            stats.insideSweeps = sweepToFixedPoint(candidates, options.work, [&](size_t n) {
                const Image& image = images[n];
                const bool stays = !image.has(Image::kBeyond) && !image.has(Image::kWide) &&
                                   visitImage(grid, level, image, [&](const CellIndex&, uint8_t v) {
                                       return v == insideValue || v == kCandidate;
                                   });
                if (!stays) store(indexOf(undecided[n]), uint8_t(CellClass::kUndecided));
                return !stays;
            });
            if (stats.insideSweeps < 0) break;
            for (int32_t n : candidates) {
                store(indexOf(undecided[size_t(n)]), insideValue);
                state[size_t(n)] = kReached;
            }
            stats.inside = int64_t(candidates.size());
        } else {
            const int64_t grown = growToFixedPoint(grid, level, undecided, sets, state, slots,
                                                   insideValue, false, options.work);
            if (grown < 0) break;
            stats.inside = grown;
        }
        // After a greatest fixed point on f alone, f^k's images may still add inside cells.
        if (sets.size() > 1 && greatest) {
            const int64_t grown = growToFixedPoint(grid, level, undecided, sets, state, slots,
                                                   insideValue, false, options.work);
            if (grown < 0) break;
            stats.inside += grown;
        }
        if (cancelled(options.work)) break;
        foundInside = foundInside || stats.inside > 0;
        images = std::vector<Image>();
        slots = std::vector<int32_t>();
        state = std::vector<uint8_t>();

        // Undecided: refined where the options say.
        std::vector<CellKey> next;
        for (int32_t n : active) {
            const CellIndex c = indexOf(undecided[size_t(n)]);
            if (grid.valueAt(level, c) != uint8_t(CellClass::kUndecided)) continue;
            ++stats.undecided;
            if (level >= options.finestLevel) continue;
            if (options.refineWhere && !options.refineWhere(level, c)) continue;
            grid.refine(level, c);
            const CellIndex child{2 * c[0], 2 * c[1], dimension > 2 ? 2 * c[2] : 0};
            for (int64_t k = 0; k < (dimension > 2 ? 2 : 1); ++k)
                for (int64_t j = 0; j < 2; ++j)
                    for (int64_t i = 0; i < 2; ++i)
                        next.push_back(keyOf({child[0] + i, child[1] + j, child[2] + k}));
        }
        stats.seconds = std::chrono::duration<double>(Clock::now() - levelStart).count();
        report.levels.push_back(stats);
        const uint64_t bytes = grid.memoryBytes() + 3 * next.size() * sizeof(CellKey);
        report.peakMemoryBytes = std::max(report.peakMemoryBytes, bytes);
        if (bytes > options.memoryLimitBytes)
            throw MemoryLimitError(options.memoryKey, "the cells need " + formatBytes(bytes) +
                                                          ", over the limit of " +
                                                          formatBytes(options.memoryLimitBytes));
        if (options.work.progress)
            options.work.progress(double(level + 1) / double(options.finestLevel + 1));
        if (next.empty()) {
            report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
            return report;
        }
        undecided = std::move(next);
    }
    report.completed = false;
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return report;
}

}  // namespace quaternia
