#include "quaternia/cellmap/cell_grid.h"

#include <algorithm>
#include <cstring>

#include <stdexcept>
#include "quaternia/cellmap/byte_record.h"

namespace quaternia {
namespace {

// Dense tile tables up to this many entries (64 MiB of uint32); hash maps beyond.
constexpr int64_t kDenseTableLimit = int64_t(1) << 24;

uint8_t loadRelaxed(const uint8_t* at) {
    return __atomic_load_n(at, __ATOMIC_RELAXED);
}

AxisRange touchedCells(const Interval& x, double lower, double size, int64_t n) {
    const double upper = lower + double(n) * size;
    AxisRange range{0, n - 1, x.lo < lower || x.hi > upper};
    if (!(x.lo <= x.hi)) return {0, n - 1, true};  // NaN: nothing known
    // A little slack either way: touching one cell too many is harmless (it can only leave a
    // cell undecided), missing one would not be.
    const double first = std::floor((x.lo - lower) / size - 1e-9);
    const double last = std::floor((x.hi - lower) / size + 1e-9);
    range.first = int64_t(std::max(0.0, std::min(first, double(n))));
    range.last = int64_t(std::max(-1.0, std::min(last, double(n - 1))));
    return range;
}

}  // namespace

CellGrid::CellGrid(int dimension, std::array<double, 3> lower, std::array<double, 3> size0,
                   std::array<int64_t, 3> cellsAtLevel0, int levels, CellClass initial)
    : dimension_(dimension), lower_(lower), size0_(size0), cells0_(cellsAtLevel0) {
    if (dimension != 2 && dimension != 3) throw std::invalid_argument("CellGrid: dimension");
    for (int a = dimension; a < 3; ++a)
        cells0_[a] = 1, size0_[a] = 1, lower_[a] = 0;
    addLevel();
    Level& top = levels_[0];
    for (int64_t k = 0; k < top.tilesPerAxis[2]; ++k)
        for (int64_t j = 0; j < top.tilesPerAxis[1]; ++j)
            for (int64_t i = 0; i < top.tilesPerAxis[0]; ++i) {
                uint8_t* tile = allocateTile(0, {i, j, k});
                std::memset(tile, int(initial), size_t(tileCells()));
            }
    while (int(levels_.size()) < levels)
        addLevel();
}

void CellGrid::addLevel() {
    const int level = int(levels_.size());
    Level next;
    int64_t entries = 1;
    for (int a = 0; a < dimension_; ++a) {
        const int64_t cells = cellsAt(level, a);
        next.tilesPerAxis[a] = (cells + (int64_t(1) << tileBits()) - 1) >> tileBits();
        entries *= next.tilesPerAxis[a];
    }
    if (entries <= kDenseTableLimit) next.dense.assign(size_t(entries), 0);
    for (int a = 0; a < 3; ++a)
        next.cellSize[a] = std::ldexp(size0_[a], -level);
    levels_.push_back(std::move(next));
}

uint8_t* CellGrid::allocateTile(int level, const CellIndex& tile) {
    Level& l = levels_[size_t(level)];
    l.tiles.push_back(std::make_unique<uint8_t[]>(size_t(tileCells())));
    l.tileOrigins.push_back(tile);
    const uint32_t number = uint32_t(l.tiles.size());
    const uint64_t key = tileKey(l, tile);
    if (!l.dense.empty())
        l.dense[key] = number;
    else
        l.sparse[key] = number;
    return l.tiles.back().get();
}

AxisRange CellGrid::cellsTouched(int level, int axis, const Interval& x) const {
    return touchedCells(x, lower_[axis], cellSize(level, axis), cellsAt(level, axis));
}

uint8_t CellGrid::ancestorValue(int level, const CellIndex& cell) const {
    const int bits = tileBits();
    CellIndex c = cell;
    int top = level;
    for (; top >= levels(); --top)  // below the finest level made: the leaves above
        for (int a = 0; a < dimension_; ++a)
            c[a] >>= 1;
    for (int l = top; l >= 0; --l) {
        const CellIndex tile{c[0] >> bits, c[1] >> bits, c[2] >> bits};
        if (const uint8_t* t = tileOf(l, tile)) {
            const uint8_t v = loadRelaxed(t + offsetInTile(c));
            // An ancestor marked refined without the child's tile: only a damaged file does that.
            return v == kRefined && l < top ? uint8_t(CellClass::kUndecided) : v;
        }
        for (int a = 0; a < dimension_; ++a)
            c[a] >>= 1;
    }
    return uint8_t(CellClass::kUndecided);  // unreachable: level 0 is whole
}

uint8_t* CellGrid::valueAddress(int level, const CellIndex& cell) {
    const int bits = tileBits();
    const uint8_t* t = tileOf(level, {cell[0] >> bits, cell[1] >> bits, cell[2] >> bits});
    return t ? const_cast<uint8_t*>(t) + offsetInTile(cell) : nullptr;
}

void CellGrid::setValue(int level, const CellIndex& cell, uint8_t value) {
    uint8_t* at = valueAddress(level, cell);
    if (!at) throw std::logic_error("CellGrid::setValue: no tile");
    __atomic_store_n(at, value, __ATOMIC_RELAXED);
}

void CellGrid::refine(int level, const CellIndex& cell) {
    if (level + 1 == levels()) addLevel();
    const int bits = tileBits();
    const CellIndex child0{cell[0] * 2, dimension_ > 1 ? cell[1] * 2 : 0,
                           dimension_ > 2 ? cell[2] * 2 : 0};
    const CellIndex tile{child0[0] >> bits, child0[1] >> bits, child0[2] >> bits};
    uint8_t* t = const_cast<uint8_t*>(tileOf(level + 1, tile));
    if (!t) {
        t = allocateTile(level + 1, tile);
        // The tile's other cells: their parents' values (classes; a refined parent's children
        // are set below or by its own refine call).
        const int64_t side = int64_t(1) << bits;
        const int64_t sideZ = dimension_ > 2 ? side : 1;
        for (int64_t k = 0; k < sideZ; ++k)
            for (int64_t j = 0; j < side; ++j)
                for (int64_t i = 0; i < side; ++i) {
                    const CellIndex c{(tile[0] << bits) + i, (tile[1] << bits) + j,
                                      (tile[2] << bits) + k};
                    CellIndex parent{c[0] >> 1, c[1] >> 1, dimension_ > 2 ? c[2] >> 1 : 0};
                    bool inside = true;
                    for (int a = 0; a < dimension_; ++a)
                        inside = inside && parent[a] < cellsAt(level, a);
                    const uint8_t v =
                        inside ? valueAt(level, parent) : uint8_t(CellClass::kOutside);
                    t[offsetInTile(c)] = v == kRefined ? uint8_t(CellClass::kUndecided) : v;
                }
    }
    setValue(level, cell, kRefined);
    const int64_t zCount = dimension_ > 2 ? 2 : 1;
    for (int64_t k = 0; k < zCount; ++k)
        for (int64_t j = 0; j < 2; ++j)
            for (int64_t i = 0; i < 2; ++i)
                t[offsetInTile({child0[0] + i, child0[1] + j, child0[2] + k})] =
                    uint8_t(CellClass::kUndecided);
}

std::array<AxisRange, 3> CellGrid::rangesUnder(int level, const CellIndex& origin,
                                               const std::array<Interval, 3>& box) const {
    // The cells of `level` under `origin`'s parent region that the box touches: origin is the
    // first child (or, at level 0, the grid's first cell) and the region 2 (or n0) cells wide.
    std::array<AxisRange, 3> ranges{};
    for (int a = 0; a < 3; ++a) {
        if (a >= dimension_) {
            ranges[a] = {0, 0, false};
            continue;
        }
        const int64_t span = level == 0 ? cells0_[a] : 2;
        AxisRange r = cellsTouched(level, a, box[a]);
        r.first = std::max(r.first, origin[a]);
        r.last = std::min(r.last, origin[a] + span - 1);
        ranges[a] = r;
    }
    return ranges;
}

CellClass CellGrid::classOfBoxAt(int level, const CellIndex& origin,
                                 const std::array<Interval, 3>& box, bool& sawInside,
                                 bool& sawOutside) const {
    const std::array<AxisRange, 3> ranges = rangesUnder(level, origin, box);
    for (int64_t k = ranges[2].first; k <= ranges[2].last; ++k)
        for (int64_t j = ranges[1].first; j <= ranges[1].last; ++j)
            for (int64_t i = ranges[0].first; i <= ranges[0].last; ++i) {
                const CellIndex cell{i, j, k};
                const uint8_t v = valueAt(level, cell);
                if (v == kRefined && level + 1 < levels()) {
                    const CellIndex child{2 * i, dimension_ > 1 ? 2 * j : 0,
                                          dimension_ > 2 ? 2 * k : 0};
                    if (classOfBoxAt(level + 1, child, box, sawInside, sawOutside) ==
                        CellClass::kUndecided)
                        return CellClass::kUndecided;
                    continue;
                }
                if (v == kRefined) return CellClass::kUndecided;  // a file's last level
                if (v == uint8_t(CellClass::kInside))
                    sawInside = true;
                else if (v == uint8_t(CellClass::kOutside))
                    sawOutside = true;
                else
                    return CellClass::kUndecided;
                if (sawInside && sawOutside) return CellClass::kUndecided;
            }
    return sawInside ? CellClass::kInside : CellClass::kOutside;
}

CellClass CellGrid::classOfBox(const std::array<Interval, 3>& box, bool beyondIsOutside) const {
    bool sawInside = false, sawOutside = false, anyCell = true;
    for (int a = 0; a < dimension_; ++a) {
        const AxisRange r = cellsTouched(0, a, box[a]);
        if (r.beyond) {
            if (!beyondIsOutside) return CellClass::kUndecided;
            sawOutside = true;
        }
        anyCell = anyCell && r.first <= r.last;
    }
    if (!anyCell) return CellClass::kOutside;  // wholly beyond the grid
    if (sawOutside && !beyondIsOutside) return CellClass::kUndecided;
    return classOfBoxAt(0, {0, 0, 0}, box, sawInside, sawOutside);
}

void CellGrid::classesInBoxAt(int level, const CellIndex& origin,
                              const std::array<Interval, 3>& box, uint8_t& classes) const {
    const std::array<AxisRange, 3> ranges = rangesUnder(level, origin, box);
    constexpr uint8_t all = kHasOutside | kHasInside | kHasUndecided;
    for (int64_t k = ranges[2].first; k <= ranges[2].last && classes != all; ++k)
        for (int64_t j = ranges[1].first; j <= ranges[1].last && classes != all; ++j)
            for (int64_t i = ranges[0].first; i <= ranges[0].last && classes != all; ++i) {
                const uint8_t v = valueAt(level, {i, j, k});
                if (v == kRefined && level + 1 < levels())
                    classesInBoxAt(level + 1,
                                   {2 * i, dimension_ > 1 ? 2 * j : 0, dimension_ > 2 ? 2 * k : 0},
                                   box, classes);
                else if (v == uint8_t(CellClass::kInside))
                    classes |= kHasInside;
                else if (v == uint8_t(CellClass::kOutside))
                    classes |= kHasOutside;
                else
                    classes |= kHasUndecided;
            }
}

uint8_t CellGrid::classesInBox(const std::array<Interval, 3>& box, bool beyondIsOutside) const {
    uint8_t classes = 0;
    bool anyCell = true;
    for (int a = 0; a < dimension_; ++a) {
        const AxisRange r = cellsTouched(0, a, box[a]);
        if (r.beyond) classes |= beyondIsOutside ? kHasOutside : kHasUndecided;
        anyCell = anyCell && r.first <= r.last;
    }
    if (anyCell) classesInBoxAt(0, {0, 0, 0}, box, classes);
    return classes;
}

CellGrid::Census CellGrid::census() const {
    Census census;
    for (int l = 0; l < levels(); ++l) {
        const Level& level = levels_[size_t(l)];
        double volume = 1;
        for (int a = 0; a < dimension_; ++a)
            volume *= cellSize(l, a);
        const int bits = tileBits();
        const int64_t side = int64_t(1) << bits;
        for (size_t t = 0; t < level.tiles.size(); ++t) {
            const CellIndex& origin = level.tileOrigins[t];
            const uint8_t* tile = level.tiles[t].get();
            for (int64_t n = 0; n < tileCells(); ++n) {
                const CellIndex c{(origin[0] << bits) + (n & (side - 1)),
                                  (origin[1] << bits) + ((n >> bits) & (side - 1)),
                                  (origin[2] << bits) + (n >> 2 * bits)};
                bool inGrid = true;
                for (int a = 0; a < dimension_; ++a)
                    inGrid = inGrid && c[a] < cellsAt(l, a);
                if (!inGrid) continue;
                // A cell counts where it is a leaf: its value is a class and, below level 0,
                // its parent was refined (else the parent, a leaf itself, counted it).
                if (l > 0 && valueAt(l - 1, {c[0] >> 1, c[1] >> 1,
                                             dimension_ > 2 ? c[2] >> 1 : 0}) != kRefined)
                    continue;
                switch (tile[offsetInTile(c)]) {
                    case uint8_t(CellClass::kOutside):
                        ++census.outside, census.outsideVolume += volume;
                        break;
                    case uint8_t(CellClass::kInside):
                        ++census.inside, census.insideVolume += volume;
                        break;
                    case kRefined:
                        break;
                    default:
                        ++census.undecided, census.undecidedVolume += volume;
                        break;
                }
            }
        }
    }
    return census;
}

uint64_t CellGrid::memoryBytes() const {
    uint64_t bytes = 0;
    for (const Level& l : levels_)
        bytes +=
            l.tiles.size() * uint64_t(tileCells() + 48) + l.dense.size() * 4 + l.sparse.size() * 32;
    return bytes;
}

void CellGrid::appendTo(std::vector<uint8_t>& out) const {
    appendValue<int32_t>(out, dimension_);
    appendValue<int32_t>(out, levels());
    for (int a = 0; a < 3; ++a) {
        appendValue<double>(out, lower_[a]);
        appendValue<double>(out, size0_[a]);
        appendValue<int64_t>(out, cells0_[a]);
    }
    for (const Level& level : levels_) {
        appendValue<uint64_t>(out, level.tiles.size());
        for (size_t t = 0; t < level.tiles.size(); ++t) {
            for (int a = 0; a < 3; ++a)
                appendValue<int64_t>(out, level.tileOrigins[t][a]);
            const size_t at = out.size();
            out.resize(at + size_t(tileCells()));
            std::memcpy(out.data() + at, level.tiles[t].get(), size_t(tileCells()));
        }
    }
}

CellGrid CellGrid::readFrom(const uint8_t*& at, const uint8_t* end) {
    CellGrid grid;
    grid.dimension_ = takeValue<int32_t>(at, end);
    const int levels = takeValue<int32_t>(at, end);
    if ((grid.dimension_ != 2 && grid.dimension_ != 3) || levels < 1 || levels > 40)
        throw std::runtime_error("bad cell grid header");
    for (int a = 0; a < 3; ++a) {
        grid.lower_[a] = takeValue<double>(at, end);
        grid.size0_[a] = takeValue<double>(at, end);
        grid.cells0_[a] = takeValue<int64_t>(at, end);
        if (!(grid.size0_[a] > 0) || grid.cells0_[a] < 1 || grid.cells0_[a] > (int64_t(1) << 20))
            throw std::runtime_error("bad cell grid geometry");
    }
    for (int l = 0; l < levels; ++l) {
        grid.addLevel();
        const uint64_t tiles = takeValue<uint64_t>(at, end);
        if (tiles > uint64_t(end - at) / uint64_t(grid.tileCells()))
            throw std::runtime_error("truncated cell grid");
        for (uint64_t t = 0; t < tiles; ++t) {
            CellIndex origin{};
            for (int a = 0; a < 3; ++a) {
                origin[a] = takeValue<int64_t>(at, end);
                if (origin[a] < 0 || origin[a] >= grid.levels_[size_t(l)].tilesPerAxis[a])
                    throw std::runtime_error("bad tile position");
            }
            if (grid.tileOf(l, origin)) throw std::runtime_error("repeated tile");
            if (end - at < grid.tileCells()) throw std::runtime_error("truncated cell grid");
            std::memcpy(grid.allocateTile(l, origin), at, size_t(grid.tileCells()));
            at += grid.tileCells();
        }
    }
    return grid;
}

}  // namespace quaternia
