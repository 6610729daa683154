// Certified escape maps of a bicomplex formula's two duplex components, for the sets that have no
// distance estimate: the bicomplex functions (exp(z) + c, sin(z) + c, ...; issue 42).
//
// Every operation of a bicomplex formula (sums, products, powers, exp, sin, ...) acts on the
// duplex form (a, b) (hypercomplex.h, duplexForm) component by component, so the orbit of
// q = (a, b) is the pair of two complex orbits a_n = f_1^n(a), b_n = f_2^n(b), f_i the formula
// with every constant replaced by its i-th duplex component. K_N asks |q_n|^2 =
// (|a_n|^2 + |b_n|^2) / 2 <= B^2 for n < N, so it lies in E_1 x E_2 with
// E_i = {w : |f_i^n(w)| <= sqrt(2) B for n < N}, a set of the complex plane. Each E_i is
// certified once on a grid of the square |Re w|, |Im w| <= sqrt(2) B: a cell is iterated as a
// disc (centre and radius; a holomorphic map takes a disc about c into one about f(c) of radius
// |f'(c)| r plus the Taylor remainder, interval/function_forms.h, so discs are first-order
// exact), and is
// - outside: some iterate n < N of the disc lies beyond sqrt(2) B, so no point of the cell is in
//   E_i and no q with that component is in K_N;
// - bounded: every iterate n < N of the disc lies within sqrt(2) B (no cell below is outside);
// - undecided otherwise (cells are split four ways, down to the finest level, while undecided).
// From the outside cells, a distance transform (Felzenszwalb and Huttenlocher) gives each cell a
// clearance: a lower bound of the distance from its centre to the nearest cell that is not
// outside. Then for q = (a, b), dist(q, K_N) >= sqrt(c_1(a)^2 + c_2(b)^2) / sqrt(2)
// (|q - y|^2 = (|a - a'|^2 + |b - b'|^2) / 2, and y in K_N has a' in E_1, b' in E_2). The
// fixed-step marcher (render/march.h) skips the samples within the clearance, so its first
// inside sample is the plain fixed steps' (docs/methods.md, "Bicomplex functions").
#pragma once

#include <array>
#include <complex>
#include <cstdint>
#include <memory>
#include <vector>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/fractal/duplex_program.h"

namespace quaternia {

// One duplex component's certified plane (header comment).
class DuplexEscapeMap {
  public:
    // The component map `program` (DuplexComponentProgram::supports), N = maxIterations, over
    // the square of half-width sqrt(2) bailout in 2^finestLevel cells per axis.
    DuplexEscapeMap(const DuplexComponentProgram& program, int maxIterations, double bailout,
                    int finestLevel);

    // A lower bound of the distance from w to E_i (0 where w's cell borders one that is not
    // outside, or is not outside itself).
    double clearance(std::complex<double> w) const;
    // Whether w's cell is outside (w is no point of E_i).
    bool outside(std::complex<double> w) const;

    // The map of these arguments from a small cache of the last few built (the explorer renders
    // one scene many times over, its slice and camera moving, and the maps depend on neither),
    // else built now.
    static std::shared_ptr<const DuplexEscapeMap> shared(const DuplexComponentProgram& program,
                                                         int maxIterations, double bailout,
                                                         int finestLevel);
    // The most memory the maps take while a scene's pair is built at `finestLevel`: two planes
    // at once, each with its clearances (2 bytes a cell) and the distance transform's two
    // grids of floats, beside the cache's other maps (2 bytes a cell each).
    static uint64_t peakBytes(int finestLevel);

  private:
    enum class Verdict { kOutside, kBounded, kUndecided };
    // Scratch for certifying: the component's map and its registers.
    struct Certifying {
        const DuplexComponentProgram& program;
        std::vector<ComplexDisc> registers;
    };
    Verdict iterate(Certifying& with, ComplexDisc cell) const;
    void certify(Certifying& with, int level, int64_t x, int64_t y);
    void computeClearance();
    int64_t cellOf(std::complex<double> w) const;

    int maxIterations_;
    double half_;      // sqrt(2) bailout, the square's half-width and E_i's radius
    int finestLevel_;  // cells_ = 2^finestLevel_
    int64_t cells_;
    double cellSize_;
    // Per finest cell: 0 not outside; else outside, with a clearance from its centre of
    // (value - 1) quarters of a cell.
    std::vector<uint16_t> outside_;
};

// Both components' maps, and what they prove about points q of the bicomplex algebra.
class DuplexEscapeMaps {
  public:
    // Programs with equal signatures (every constant has equal duplex parts) are one map,
    // certified once.
    DuplexEscapeMaps(const std::array<DuplexComponentProgram, 2>& programs, int maxIterations,
                     double bailout, int finestLevel);

    // A lower bound of |q - y| over y in K_N.
    double clearance(const Hypercomplex& q) const;
    // Whether a component's cell is outside: q is no point of K_N.
    bool outside(const Hypercomplex& q) const;

  private:
    std::array<std::shared_ptr<const DuplexEscapeMap>, 2> maps_;  // the second may be the first
};

}  // namespace quaternia
