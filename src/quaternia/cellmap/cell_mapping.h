// Cell mapping with interval arithmetic: which cells of a grid certainly lie outside the filled
// Julia set K of a map f, which certainly inside, and which stay undecided (they may hold a
// point of the Julia set J = the boundary of K). After Figueiredo, Nehab, Stolfi and Oliveira,
// "Rigorous bounds for polynomial Julia sets", Journal of Computational Dynamics 3(2), 2016,
// with the inside proven by a trapped region instead of their graph of gray cells.
//
// Each cell's image f(cell) is enclosed in a box by interval arithmetic (BoxMap::image); the
// cells that box touches are the cell's successors, and every point of the cell maps into
// their union. Then, on the cells still undecided at a level:
// - outside: the least fixed point of "the cell lies beyond the escape radius (BoxMap::escapes,
//   a theorem for the formula), or all its successors are outside". Every point of an outside
//   cell maps into outside cells, and by induction reaches the escape region: its orbit tends
//   to infinity. The part of an image beyond the grid counts as outside, since the grid holds
//   the escape ball.
// - inside: the greatest fixed point of "all the cell's successors are inside or candidates",
//   starting from every undecided cell. The candidates left form a region U with f(U) inside
//   U together with the inside cells of earlier levels (U is trapped), so every orbit from U
//   stays in the grid: U lies in K. For a connected K with an attracting cycle, U grows from
//   the cycle's basin out to a cell or two from J; for a Cantor set it is empty, as it must be
//   (K has no interior).
// - undecided: the rest. The undecided cells are then cut in two along every axis and the
//   next level decides their children, which the finer successors of the children let it do
//   ever nearer J.
// Both fixed points are unique, so the classes do not depend on the order the cells are
// visited in, or on the number of threads (the sweeps run in parallel with relaxed atomic
// byte updates, which only ever move a cell towards its final class).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "quaternia/cellmap/cell_grid.h"
#include "quaternia/interval/interval.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

using Box3 = std::array<Interval, 3>;

// f on boxes in the grid's coordinates (axes past the grid's dimension unused).
struct BoxMap {
    // A box holding f(p) for every p in the box.
    std::function<Box3(const Box3&)> image;
    // True only where every point of the box lies beyond the escape radius.
    std::function<bool(const Box3&)> escapes;
    // Optional: a box holding f^k(p) for every p in the box, for the iterates k of `iterates`.
    // A cell is outside where f^k's image touches outside cells only, inside where inside
    // cells only, as for f: the orbit reaches them after k steps. Where f turns and stretches
    // little, each step's box wraps a turned square, and boxes grow faster than the map
    // stretches (the undecided band swells about a weakly repelling point whose multiplier
    // turns, as the rabbit's alpha fixed point); f^k's image by the mean value form turns once.
    std::function<Box3(const Box3&, int k)> iterateImage;
    std::vector<int> iterates;
};

struct CellMappingOptions {
    // Whether an undecided cell of a level is cut into its children (levels up to the grid's
    // finest are made as needed; `finestLevel` caps them). Null refines every one.
    std::function<bool(int level, const CellIndex& cell)> refineWhere;
    int finestLevel = 0;
    uint64_t memoryLimitBytes = uint64_t(4) << 30;
    std::string memoryKey = "--resolution";  // named by the MemoryLimitError
    WorkOptions work;
};

struct CellMappingLevel {
    int level = 0;
    int64_t cells = 0;  // undecided cells the level started with
    int64_t outside = 0, inside = 0, undecided = 0;
    int insideSweeps = 0;  // sweeps of the greatest fixed point (0 where the inside grew)
    double seconds = 0;
};

struct CellMappingReport {
    std::vector<CellMappingLevel> levels;
    uint64_t peakMemoryBytes = 0;
    double seconds = 0;
    bool completed = true;  // false when cancelled (the grid is then not certified)
};

// Classifies the grid's undecided cells of level 0 and refines as the options say, level by
// level, in place. Cells already outside or inside stay so (they are proven). Throws
// MemoryLimitError (options.memoryKey) where the cells outgrow options.memoryLimitBytes.
CellMappingReport classifyCells(CellGrid& grid, const BoxMap& map,
                                const CellMappingOptions& options);

}  // namespace quaternia
