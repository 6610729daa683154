// The cells of a cell mapping (cell_mapping.h): an adaptive grid over a box of R^2 or R^3, kept
// as a pyramid of levels. Level 0 is a uniform grid; each level halves the cells of the one
// above along every axis, but only below the cells that were refined, so the finest cells lie
// where the classes are still being decided (along the Julia set) and the rest of the box stays
// coarse. A level is stored in tiles of 2^kTileBits cells per axis (64 x 64 in 2D, 16^3 in 3D),
// allocated where a cell of the level above was refined; a cell whose tile was never allocated
// has its ancestor's class.
//
// Classes are bytes: CellClass's outside (0), undecided (128) and inside (255), the values of
// the classes PNGs, plus kRefined for a cell whose children at the next level hold its classes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "quaternia/interval/interval.h"

namespace quaternia {

enum class CellClass : uint8_t { kOutside = 0, kUndecided = 128, kInside = 255 };

constexpr uint8_t kRefined = 64;  // a cell value: see the children at the next level

// A cell's integer coordinates at one level (unused axes 0).
using CellIndex = std::array<int64_t, 3>;

// The cells of one axis at a level that a coordinate interval touches, clipped to the grid:
// [first, last], empty where first > last; `beyond` where part of the interval lies outside
// the grid. A bound on a cell boundary touches the cells on both sides (cells are closed).
struct AxisRange {
    int64_t first, last;
    bool beyond;
};

class CellGrid {
  public:
    CellGrid() = default;
    // A grid over the box [lower, lower + cellsAtLevel0 * size0] in `dimension` (2 or 3) axes,
    // every cell of level 0 `initial`. `levels` >= 1 levels in all.
    CellGrid(int dimension, std::array<double, 3> lower, std::array<double, 3> size0,
             std::array<int64_t, 3> cellsAtLevel0, int levels, CellClass initial);

    int dimension() const { return dimension_; }
    int levels() const { return int(levels_.size()); }
    int finestLevel() const { return levels() - 1; }
    const std::array<double, 3>& lower() const { return lower_; }
    // Cells along axis a at level l (a full grid would have that many).
    int64_t cellsAt(int level, int axis) const { return cells0_[axis] << level; }
    double cellSize(int level, int axis) const {
        return level < levels() ? levels_[size_t(level)].cellSize[axis]
                                : std::ldexp(size0_[axis], -level);
    }
    // The box of a cell, its bounds as exact doubles (neighbours share their bounds, so the
    // cells of a level cover the grid's box without gaps).
    double cellLower(int level, int axis, int64_t index) const {
        return lower_[axis] + double(index) * cellSize(level, axis);
    }
    double upperBound(int axis) const { return cellLower(0, axis, cells0_[axis]); }
    AxisRange cellsTouched(int level, int axis, const Interval& x) const;

    // The value of a cell (its class, or kRefined) at a level: its own where its tile exists,
    // else its nearest ancestor's (never kRefined then). The index must lie in the grid. Reads
    // and writes of values are relaxed atomic byte accesses, so that the cell mapping's
    // threads may update cells while others read them.
    uint8_t valueAt(int level, const CellIndex& cell) const {
        if (level < levels()) {  // the cell's own tile, the common case, inline
            const int bits = tileBits();
            if (const uint8_t* t =
                    tileOf(level, {cell[0] >> bits, cell[1] >> bits, cell[2] >> bits})) {
                const uint8_t v = __atomic_load_n(t + offsetInTile(cell), __ATOMIC_RELAXED);
                return v;
            }
        }
        return ancestorValue(level, cell);
    }
    // Calls visit(cell, value) for the cells [first, last] of a level (inclusive, per axis),
    // row by row, one tile lookup per run of a row within a tile, until visit returns false;
    // returns whether every visit returned true.
    template <typename Visit>
    bool visitCells(int level, const CellIndex& first, const CellIndex& last, Visit&& visit) const {
        const int bits = tileBits();
        const int64_t side = int64_t(1) << bits;
        for (int64_t k = first[2]; k <= last[2]; ++k)
            for (int64_t j = first[1]; j <= last[1]; ++j)
                for (int64_t i = first[0]; i <= last[0];) {
                    const int64_t runEnd = std::min(last[0], ((i >> bits) + 1) * side - 1);
                    const uint8_t* t = level < levels()
                                           ? tileOf(level, {i >> bits, j >> bits, k >> bits})
                                           : nullptr;
                    for (; i <= runEnd; ++i) {
                        const CellIndex cell{i, j, k};
                        const uint8_t v =
                            t ? __atomic_load_n(t + offsetInTile(cell), __ATOMIC_RELAXED)
                              : ancestorValue(level, cell);
                        if (!visit(cell, v)) return false;
                    }
                }
        return true;
    }
    // A number for each cell of a level's allocated tiles, in [0, tileCount(level) * cells per
    // tile): where a caller keeps its own per-cell data. -1 where the cell's tile does not
    // exist.
    int64_t cellSlot(int level, const CellIndex& cell) const {
        const int bits = tileBits();
        const uint32_t number =
            tileNumber(level, {cell[0] >> bits, cell[1] >> bits, cell[2] >> bits});
        return number ? int64_t(number - 1) * tileCells() + int64_t(offsetInTile(cell)) : -1;
    }
    int64_t slotCount(int level) const {
        return int64_t(levels_[size_t(level)].tiles.size()) * tileCells();
    }
    // Sets a cell's value; its tile must exist (allocateChildren made it).
    void setValue(int level, const CellIndex& cell, uint8_t value);
    // The address of a cell's byte in its tile, null where the tile does not exist (for the
    // relaxed atomic updates of the parallel fixpoints).
    uint8_t* valueAddress(int level, const CellIndex& cell);

    // Marks a cell kRefined and sets its 2^dimension children at level + 1 undecided,
    // allocating their tile (the tile's other cells take their parents' values). Not
    // thread-safe. Adds a level when level + 1 == levels().
    void refine(int level, const CellIndex& cell);

    // The class of every point of the box (coordinates per axis; the axes past dimension()
    // ignored): outside or inside where every cell the box touches has that class, else
    // undecided. Where the box leaves the grid, the part beyond counts as outside when
    // `beyondIsOutside` (the grid holds the escape ball), else makes the box undecided. Walks
    // the pyramid from level 0, descending only into refined cells.
    CellClass classOfBox(const std::array<Interval, 3>& box, bool beyondIsOutside) const;
    // The classes of the leaf cells the box touches, as bits kHasOutside | kHasInside |
    // kHasUndecided (beyond the grid as classOfBox): whether a box that is not all one class
    // may still hold an inside point.
    static constexpr uint8_t kHasOutside = 1, kHasInside = 2, kHasUndecided = 4;
    uint8_t classesInBox(const std::array<Interval, 3>& box, bool beyondIsOutside) const;

    // Counts of the leaf cells per class, and their volumes (area in 2D) in grid units.
    struct Census {
        int64_t outside = 0, inside = 0, undecided = 0;
        double outsideVolume = 0, insideVolume = 0, undecidedVolume = 0;
    };
    Census census() const;
    uint64_t memoryBytes() const;

    // Serialisation: the level geometry and every allocated tile (certified_set.cpp frames and
    // compresses it).
    void appendTo(std::vector<uint8_t>& out) const;
    // Reads what appendTo wrote from bytes [at, end), advancing at; throws std::runtime_error on
    // a truncated or inconsistent record.
    static CellGrid readFrom(const uint8_t*& at, const uint8_t* end);

    static constexpr int kTileBits2D = 6, kTileBits3D = 4;

  private:
    struct Level {
        std::array<int64_t, 3> tilesPerAxis{1, 1, 1};
        std::array<double, 3> cellSize{1, 1, 1};
        // Dense table of tile numbers (+1; 0 = none) where it is small, else a hash map.
        std::vector<uint32_t> dense;
        std::unordered_map<uint64_t, uint32_t> sparse;
        std::vector<std::unique_ptr<uint8_t[]>> tiles;
        std::vector<CellIndex> tileOrigins;  // the tile coordinates of each tile
    };
    int tileBits() const { return dimension_ == 2 ? kTileBits2D : kTileBits3D; }
    int64_t tileCells() const { return int64_t(1) << (tileBits() * dimension_); }
    uint64_t tileKey(const Level& level, const CellIndex& tile) const {
        return uint64_t(tile[0]) +
               uint64_t(level.tilesPerAxis[0]) *
                   (uint64_t(tile[1]) + uint64_t(level.tilesPerAxis[1]) * uint64_t(tile[2]));
    }
    // The tile's number + 1 in its level's list, 0 where it does not exist.
    uint32_t tileNumber(int level, const CellIndex& tile) const {
        const Level& l = levels_[size_t(level)];
        const uint64_t key = tileKey(l, tile);
        if (!l.dense.empty()) return l.dense[key];
        auto found = l.sparse.find(key);
        return found != l.sparse.end() ? found->second : 0;
    }
    const uint8_t* tileOf(int level, const CellIndex& tile) const {
        const uint32_t number = tileNumber(level, tile);
        return number ? levels_[size_t(level)].tiles[number - 1].get() : nullptr;
    }
    size_t offsetInTile(const CellIndex& cell) const {
        const int bits = tileBits();
        const int64_t mask = (int64_t(1) << bits) - 1;
        return size_t((cell[0] & mask) + ((cell[1] & mask) << bits) +
                      ((cell[2] & mask) << 2 * bits));
    }
    uint8_t ancestorValue(int level, const CellIndex& cell) const;
    void addLevel();
    uint8_t* allocateTile(int level, const CellIndex& tile);
    std::array<AxisRange, 3> rangesUnder(int level, const CellIndex& origin,
                                         const std::array<Interval, 3>& box) const;
    void classesInBoxAt(int level, const CellIndex& origin, const std::array<Interval, 3>& box,
                        uint8_t& classes) const;
    CellClass classOfBoxAt(int level, const CellIndex& cell, const std::array<Interval, 3>& box,
                           bool& sawInside, bool& sawOutside) const;

    int dimension_ = 2;
    std::array<double, 3> lower_{}, size0_{};
    std::array<int64_t, 3> cells0_{1, 1, 1};
    std::vector<Level> levels_;
};

}  // namespace quaternia
