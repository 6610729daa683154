#include "quaternia/algebra/top_degree_minimum.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <mutex>
#include <queue>
#include <utility>

#include "quaternia/algebra/polynomial_terms.h"

namespace quaternia {
namespace {

using terms::evaluateTerm;
using terms::normProduct;
using terms::timesCoefficient;

// ---- Certified minimum of |P_d| on the unit sphere ---------------------------------------
//
// m = min |P_d(u)| over |u| = 1 sets the escape radius, so it must never be overestimated. A
// branch and bound over S^3 certifies it: S^3 is covered by the 8 faces of the cube [-1, 1]^4
// seen through p -> p / |p|, each face is cut into cubic cells, every cell gets a lower bound
// from a Taylor model about its centre, and the cell with the lowest bound is split first.

// P_d at c with its derivatives along the tangent directions t_a = c e_a (e = i, j, k), which
// are orthonormal and orthogonal to c.
struct TangentJet {
    Quaternion value;
    std::array<Quaternion, 3> first{};
    std::array<Quaternion, 6> second{};  // (a, b) = (kPairA[p], kPairB[p])
};
constexpr std::array<int, 6> kPairA = {0, 0, 0, 1, 1, 2};
constexpr std::array<int, 6> kPairB = {0, 1, 2, 1, 2, 2};

// Forward mode as in differentiateTerm: appending "z a" to v maps the second derivative
// D_a D_b v to (D_a D_b v z + D_a v t_b + D_b v t_a) a.
void accumulateJet(const Term& term, const Quaternion& c, const std::array<Quaternion, 3>& t,
                   TangentJet& jet) {
    const std::vector<Quaternion>& a = term.coefficients;
    TangentJet j;
    j.value = a[0];
    for (size_t i = 1; i < a.size(); ++i) {
        for (int p = 0; p < 6; ++p) {
            const int x = kPairA[p], y = kPairB[p];
            j.second[p] =
                timesCoefficient(j.second[p] * c + j.first[x] * t[y] + j.first[y] * t[x], a[i]);
        }
        for (int x = 0; x < 3; ++x)
            j.first[x] = timesCoefficient(j.first[x] * c + j.value * t[x], a[i]);
        j.value = timesCoefficient(j.value * c, a[i]);
    }
    jet.value += j.value;
    for (int x = 0; x < 3; ++x)
        jet.first[x] += j.first[x];
    for (int p = 0; p < 6; ++p)
        jet.second[p] += j.second[p];
}

// The top-degree part P_d, with A = the sum of its terms' norm products. Expanding
// P_d(c + v) = sum_j P_j(v) by the degree j in v (|c| = 1), P_j picks j of the d z's to take
// v, so |P_j(v)| <= binom(d, j) A |v|^j.
class TopDegreePart {
  public:
    TopDegreePart(const std::vector<Term>& terms, int degree) : degree_(degree) {
        for (const Term& term : terms) {
            if (term.degree() != degree) continue;
            top_.push_back(term);
            normSum_ += normProduct(term);
        }
    }
    const std::vector<Term>& terms() const { return top_; }
    int degree() const { return degree_; }
    double normSum() const { return normSum_; }  // an upper bound of |P_d| on S^3
    // |P_d(u) - P_d(v)| <= d A |u - v| on the unit ball (d telescoped differences).
    double lipschitz() const { return degree_ * normSum_; }
    // sum_{j >= k} binom(d, j) A delta^j: bounds |P_{>=k}(v)| for |v| <= delta.
    double tailBound(int k, double delta) const {
        double sum = 0, binomial = 1, power = 1;
        for (int j = 1; j <= degree_; ++j) {
            binomial = binomial * (degree_ - j + 1) / j;
            power *= delta;
            if (j >= k) sum += binomial * power;
        }
        return sum * normSum_;
    }
    double normAt(const Quaternion& u) const {
        Quaternion sum;
        for (const Term& term : top_)
            sum += evaluateTerm(term, u);
        return norm(sum);
    }
    TangentJet jet(const Quaternion& c) const {
        const std::array<Quaternion, 3> t = {c * kUnitI, c * kUnitJ, c * kUnitK};
        TangentJet jet;
        for (const Term& term : top_)
            accumulateJet(term, c, t, jet);
        return jet;
    }
    // m >= A_t - (A - A_t) for the largest term t: a floor that needs no search.
    double dominanceBound() const {
        double largest = 0;
        for (const Term& term : top_)
            largest = std::max(largest, normProduct(term));
        return std::max(0.0, 2 * largest - normSum_);
    }

  private:
    int degree_;
    std::vector<Term> top_;
    double normSum_ = 0;
};

using Matrix3 = std::array<std::array<double, 3>, 3>;

// Cyclic Jacobi rotations: a becomes (nearly) diagonal, a_out = v^T a_in v with v orthogonal.
void jacobiDiagonalize(Matrix3& a, Matrix3& v) {
    v = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int sweep = 0; sweep < 6; ++sweep) {
        const double diagonal = std::abs(a[0][0]) + std::abs(a[1][1]) + std::abs(a[2][2]);
        const double off = std::abs(a[0][1]) + std::abs(a[0][2]) + std::abs(a[1][2]);
        if (off <= 1e-15 * diagonal) return;
        for (int p = 0; p < 2; ++p) {
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                const double t =
                    (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
                const double cs = 1 / std::sqrt(t * t + 1), sn = t * cs;
                for (int k = 0; k < 3; ++k) {
                    const double akp = a[k][p], akq = a[k][q], vkp = v[k][p], vkq = v[k][q];
                    a[k][p] = cs * akp - sn * akq, a[k][q] = sn * akp + cs * akq;
                    v[k][p] = cs * vkp - sn * vkq, v[k][q] = sn * vkp + cs * vkq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = cs * apk - sn * aqk, a[q][k] = sn * apk + cs * aqk;
                }
            }
        }
    }
}

// min of g w + w^T m w / 2 over |w| <= delta in R^3: after diagonalising m, a sum of 1D
// minima over |w_i| <= delta (the box holds the ball). What the rotations leave off the
// diagonal is moved onto it, 2 |m_ij w_i w_j| <= |m_ij| (w_i^2 + w_j^2), so the bound holds
// however far the rotations converged.
double quadraticMinimum(const std::array<double, 3>& g, Matrix3 m, double delta) {
    Matrix3 v{};
    jacobiDiagonalize(m, v);
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
        double lambda = m[i][i], gi = 0;
        for (int j = 0; j < 3; ++j) {
            if (j != i) lambda -= std::abs(m[i][j]);
            gi += v[j][i] * g[j];
        }
        const bool inside = lambda > 0 && std::abs(gi) < lambda * delta;
        sum +=
            inside ? -gi * gi / (2 * lambda) : -std::abs(gi) * delta + lambda * delta * delta / 2;
    }
    return sum;
}

// A lower bound of psi = |P_d|^2 over the sphere within distance delta of the unit c.
// Write u = c + v, v = w + s c with w tangent and s = -|v|^2 / 2, a = P_d(c), J its
// derivative. Euler's relations for the homogeneous P_d (J c = d a, D^2 P_d(c)[w, c] =
// (d - 1) J w) turn |a + P_1(v) + P_2(v) + P_{>=3}(v)|^2 into
//   psi(u) = |a|^2 + [G.w + w^T (K - 2 d |a|^2 I) w / 2] + (2d - 1) s G.w
//            + 2 d (d - 1) s^2 |a|^2 + R,
// G = 2 J^T a and K = 2 (J^T J + <a, D^2 P_d>) the tangent gradient and Hessian of psi, and
// R = 2 <a, P_{>=3}> + 2 <P_1, P_{>=2}> + |P_{>=2}|^2 >= -2 |a| T_3 - 2 |P_1| T_2 with T_k
// from tailBound. The bracket is quadraticMinimum, the s^2 term is >= 0 and |s| <= delta^2/2.
// Unlike <n, P_d>, psi keeps the second-order growth of |P_d| when P_d turns.
double psiLowerBound(const TopDegreePart& part, const TangentJet& jet, double delta) {
    const double psi = normSquared(jet.value);
    std::array<double, 3> g{};
    Matrix3 k{}, gram{};
    for (int p = 0; p < 6; ++p) {
        const int a = kPairA[p], b = kPairB[p];
        gram[a][b] = gram[b][a] = dot(jet.first[a], jet.first[b]);
        k[a][b] = k[b][a] = 2 * (gram[a][b] + dot(jet.value, jet.second[p]));
    }
    double jacobianNorm2 = 0;  // |J w|^2 <= this |w|^2 (Gershgorin on J^T J)
    for (int a = 0; a < 3; ++a) {
        g[a] = 2 * dot(jet.value, jet.first[a]);
        k[a][a] -= 2 * part.degree() * psi;
        jacobianNorm2 = std::max(
            jacobianNorm2, std::abs(gram[a][0]) + std::abs(gram[a][1]) + std::abs(gram[a][2]));
    }
    const double d = part.degree(), delta2 = delta * delta;
    const double gradient = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    const double valueNorm = std::sqrt(psi);
    const double linear = std::sqrt(jacobianNorm2) * delta + d * valueNorm * delta2 / 2;  // |P_1|
    const double delta3 = delta2 * delta;
    const double taylor =
        psi + quadraticMinimum(g, k, delta) - (2 * d - 1) * gradient * delta3 / 2 -
        2 * valueNorm * part.tailBound(3, delta) - 2 * linear * part.tailBound(2, delta);
    // Far from the minimum the first-order |P_d(u)| >= |a| - |P_1(v)| - |P_{>=2}(v)| is better.
    const double firstOrder = std::max(0.0, valueNorm - linear - part.tailBound(2, delta));
    return std::max(taylor, firstOrder * firstOrder);
}

// A cell of the branch and bound: the cube [centre - h, centre + h]^3 on the face
// x_axis = sign of [-1, 1]^4.
struct Cell {
    double lowerBound = 0;
    double centreValue = 0;  // |P_d| at the centre
    int face = 0;            // axis = face / 2, sign = face % 2 ? -1 : +1
    std::array<double, 3> centre{};
    double halfWidth = 0;
    bool operator>(const Cell& other) const { return lowerBound > other.lowerBound; }
};

// The cell's centre on S^3, and rho^2 with rho = the least |p| over the cell's points p.
std::pair<Quaternion, double> cellCentre(const Cell& cell) {
    Quaternion p;
    double rho2 = 1;
    for (int k = 0, free = 0; k < 4; ++k) {
        if (k == cell.face / 2) {
            p[k] = cell.face % 2 ? -1.0 : 1.0;
            continue;
        }
        p[k] = cell.centre[free++];
        const double gap = std::max(0.0, std::abs(p[k]) - cell.halfWidth);
        rho2 += gap * gap;
    }
    return {normalize(p), rho2};
}

// Bounds |P_d| from below on a cell. Every point p of the cell has |p| >= rho, and
// p -> p / |p| = pi(p / rho), pi the projection onto the unit ball, is 1/rho-Lipschitz there:
// the cell lies within delta = sqrt(3) h / rho of its centre c on the sphere. The bound is the
// larger of |P_d(c)| - L delta and the psi model's.
void boundCell(const TopDegreePart& part, Cell& cell) {
    const auto [c, rho2] = cellCentre(cell);
    const TangentJet jet = part.jet(c);
    cell.centreValue = norm(jet.value);
    const double delta = std::min(2.0, std::sqrt(3.0 / rho2) * cell.halfWidth);
    const double lipschitz = cell.centreValue - part.lipschitz() * delta;
    const double taylor = std::sqrt(std::max(0.0, psiLowerBound(part, jet, delta)));
    cell.lowerBound = std::max(lipschitz, taylor);
}

// An upper bound on m sharper than the cells' centres: a pattern search on S^3 from u that
// tries u +- step t_a, renormalised, and halves the step when none is lower.
double searchDownhill(const TopDegreePart& part, Quaternion u) {
    double value = part.normAt(u);
    double step = 0.05;
    for (int iteration = 0; iteration < 400 && step > 1e-9; ++iteration) {
        const std::array<Quaternion, 3> t = {u * kUnitI, u * kUnitJ, u * kUnitK};
        bool improved = false;
        for (int n = 0; n < 6 && !improved; ++n) {
            const Quaternion v = normalize(u + t[n / 2] * (n % 2 ? -step : step));
            const double f = part.normAt(v);
            if (f < value) value = f, u = v, improved = true;
        }
        if (!improved) step /= 2;
    }
    return value;
}

constexpr double kRelativeGap = 1e-3;      // stop when (best - bound) / best is below this
constexpr double kMaxWork = 48000;         // cells times the top terms' summed degree
constexpr double kNegligible = 1e-7;       // |P_d| below this times A: treated as vanishing
constexpr double kRoundingMargin = 1e-12;  // times A: floating-point slack in |P_d|
constexpr int kInitial = 4;                // each face starts as 4^3 cells
constexpr int kDescents = 8;               // pattern searches from the lowest initial centres

// Best first: the cell with the lowest bound is split into 8 until the certified bound is
// within kRelativeGap of the best value seen, or the work cap is reached (a deterministic cap,
// so the bound and with it the escape radius never depend on the machine's speed).
double certifiedMinimum(const TopDegreePart& part) {
    const double scale = part.normSum(), floor = part.dominanceBound();
    int degrees = 0;
    for (const Term& term : part.terms())
        degrees += term.degree();
    const int maxCells = std::max(4 * 8 * kInitial * kInitial * kInitial, int(kMaxWork / degrees));

    std::vector<Cell> initial;
    for (int face = 0; face < 8; ++face) {
        for (int n = 0; n < kInitial * kInitial * kInitial; ++n) {
            Cell cell{0, 0, face, {}, 1.0 / kInitial};
            for (int k = 0, index = n; k < 3; ++k, index /= kInitial) {
                cell.centre[k] = -1 + (2 * (index % kInitial) + 1) * cell.halfWidth;
            }
            boundCell(part, cell);
            initial.push_back(cell);
        }
    }
    auto byValue = [](const Cell& a, const Cell& b) { return a.centreValue < b.centreValue; };
    std::partial_sort(initial.begin(), initial.begin() + kDescents, initial.end(), byValue);
    double best = scale;
    for (int n = 0; n < kDescents; ++n) {
        best = std::min(best, searchDownhill(part, cellCentre(initial[n]).first));
    }
    std::priority_queue<Cell, std::vector<Cell>, std::greater<>> cells(std::greater<>{},
                                                                       std::move(initial));
    for (int evaluated = int(cells.size());; evaluated += 8) {
        const double bound = std::max(floor, cells.top().lowerBound) - kRoundingMargin * scale;
        if (best <= kNegligible * scale) return 0;
        if (bound >= best * (1 - kRelativeGap) || evaluated >= maxCells) {
            return std::max(0.0, bound);
        }
        const Cell cell = cells.top();
        cells.pop();
        for (int child = 0; child < 8; ++child) {
            Cell c{0, 0, cell.face, cell.centre, cell.halfWidth / 2};
            for (int k = 0; k < 3; ++k)
                c.centre[k] += (child >> k & 1 ? 1 : -1) * c.halfWidth;
            boundCell(part, c);
            best = std::min(best, c.centreValue);
            cells.push(c);
        }
    }
}

// certifiedMinimum takes milliseconds (about 20 for z i z + 0.5 z^2 + c) and depends on the
// top-degree terms alone, which stay while the explorer's c and lower terms change from query to
// query: the last results are kept, keyed by the terms' coefficients exactly (the result is a
// deterministic function of them).
double rememberedMinimum(const TopDegreePart& part) {
    constexpr std::size_t kRemembered = 16;
    static std::mutex mutex;
    static std::deque<std::pair<std::vector<double>, double>> remembered;  // the newest last
    std::vector<double> key{double(part.degree())};
    for (const Term& term : part.terms()) {
        for (const Quaternion& q : term.coefficients)
            key.insert(key.end(), {q.w, q.x, q.y, q.z});
    }
    {
        const std::lock_guard lock(mutex);
        for (const auto& [coefficients, minimum] : remembered) {
            if (coefficients == key) return minimum;
        }
    }
    const double minimum = certifiedMinimum(part);
    const std::lock_guard lock(mutex);
    remembered.emplace_back(std::move(key), minimum);
    if (remembered.size() > kRemembered) remembered.pop_front();
    return minimum;
}

}  // namespace

// With one top term |T(u)| = A_T exactly. With several, the terms can cancel (z i z - i z^2
// vanishes on span{1, i}, docs/facts.md, Escape radius and bounding sphere), so a branch and bound
// over S^3 certifies the minimum.
double certifiedTopDegreeMinimum(const std::vector<Term>& terms, int degree) {
    const TopDegreePart part(terms, degree);
    if (part.terms().size() == 1) return normProduct(part.terms()[0]);
    if (part.terms().empty()) return 0;
    return rememberedMinimum(part);
}

}  // namespace quaternia
