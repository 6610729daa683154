#include "quaternia/dynamics/cycle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace quaternia {
namespace {

using Complex = std::complex<double>;
template <std::size_t N>
using ComplexMatrix = std::array<std::array<Complex, N>, N>;

Classification classifyModuli(double smallest, double largest) {
    auto unsureNear = [](double value, double boundary) {
        double gap = std::abs(value - boundary);
        return gap > kClassTolerance && gap < kUnsureBand;
    };
    Classification result;
    if (largest <= kClassTolerance) {
        result.stability = Stability::Superattracting;
    } else if (largest < 1 - kClassTolerance) {
        result.stability = Stability::Attracting;
    } else if (smallest > 1 + kClassTolerance) {
        result.stability = Stability::Repelling;
    } else if (smallest < 1 - kClassTolerance && largest > 1 + kClassTolerance) {
        result.stability = Stability::Saddle;
    } else if (largest <= 1 + kClassTolerance) {
        result.stability = Stability::Neutral;
    } else {
        // The smallest is ~1 and some are outside: weakly repelling.
        result.stability = Stability::Repelling;
        result.unsure = true;
    }
    result.unsure = result.unsure || unsureNear(largest, 0) || unsureNear(largest, 1) ||
                    unsureNear(smallest, 1);
    return result;
}

// Real Givens rotations on rows and columns (i - 1, i) zero the entries below the
// subdiagonal: a similarity, so the eigenvalues are kept.
template <std::size_t N>
ComplexMatrix<N> hessenberg(Matrix<N> a) {
    constexpr int n = int(N);
    for (int k = 0; k < n - 2; ++k) {
        for (int i = n - 1; i >= k + 2; --i) {
            double x = a[i - 1][k], y = a[i][k], r = std::hypot(x, y);
            if (r == 0) continue;
            double c = x / r, s = y / r;
            for (int j = 0; j < n; ++j) {
                double t1 = a[i - 1][j], t2 = a[i][j];
                a[i - 1][j] = c * t1 + s * t2;
                a[i][j] = -s * t1 + c * t2;
            }
            for (int j = 0; j < n; ++j) {
                double t1 = a[j][i - 1], t2 = a[j][i];
                a[j][i - 1] = c * t1 + s * t2;
                a[j][i] = -s * t1 + c * t2;
            }
        }
    }
    ComplexMatrix<N> h;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j)
            h[i][j] = a[i][j];
    }
    return h;
}

// The eigenvalue of the trailing 2x2 block of rows/columns [hi - 1, hi] nearer its last
// diagonal entry (Wilkinson's shift).
template <std::size_t N>
Complex wilkinsonShift(const ComplexMatrix<N>& h, int hi) {
    Complex a = h[hi - 1][hi - 1], b = h[hi - 1][hi], c = h[hi][hi - 1], d = h[hi][hi];
    Complex half = 0.5 * (a + d), root = std::sqrt(half * half - (a * d - b * c));
    Complex e1 = half + root, e2 = half - root;
    return std::abs(e1 - d) < std::abs(e2 - d) ? e1 : e2;
}

// One shifted QR step H - s I = QR, H <- RQ + s I on the unreduced block [lo, hi].
template <std::size_t N>
void qrStep(ComplexMatrix<N>& h, int lo, int hi, Complex shift) {
    std::array<std::pair<Complex, Complex>, N - 1> rotations;
    for (int k = lo; k <= hi; ++k)
        h[k][k] -= shift;
    for (int k = lo; k < hi; ++k) {
        Complex x = h[k][k], y = h[k + 1][k];
        double r = std::hypot(std::abs(x), std::abs(y));
        Complex c = r > 0 ? x / r : 1.0, s = r > 0 ? y / r : 0.0;
        rotations[k - lo] = {c, s};
        for (int j = k; j <= hi; ++j) {
            Complex t1 = h[k][j], t2 = h[k + 1][j];
            h[k][j] = std::conj(c) * t1 + std::conj(s) * t2;
            h[k + 1][j] = -s * t1 + c * t2;
        }
    }
    for (int k = lo; k < hi; ++k) {
        auto [c, s] = rotations[k - lo];
        for (int i = lo; i <= std::min(k + 2, hi); ++i) {
            Complex t1 = h[i][k], t2 = h[i][k + 1];
            h[i][k] = c * t1 + s * t2;
            h[i][k + 1] = -std::conj(s) * t1 + std::conj(c) * t2;
        }
    }
    for (int k = lo; k <= hi; ++k)
        h[k][k] += shift;
}

}  // namespace

std::string toString(Stability stability) {
    switch (stability) {
        case Stability::Superattracting:
            return "superattracting";
        case Stability::Attracting:
            return "attracting";
        case Stability::Neutral:
            return "neutral";
        case Stability::Repelling:
            return "repelling";
        case Stability::Saddle:
            return "saddle";
    }
    return "unknown";
}

Classification classifyMultiplier(std::complex<double> lambda) {
    double modulus = std::abs(lambda);
    return classifyModuli(modulus, modulus);
}

Classification classifyEigenvalues(const std::vector<std::complex<double>>& eigenvalues) {
    double smallest = std::numeric_limits<double>::infinity(), largest = 0;
    for (Complex e : eigenvalues) {
        smallest = std::min(smallest, std::abs(e));
        largest = std::max(largest, std::abs(e));
    }
    return classifyModuli(smallest, largest);
}

template <std::size_t N>
Matrix<N> identityMatrix() {
    Matrix<N> m{};
    for (std::size_t i = 0; i < N; ++i)
        m[i][i] = 1;
    return m;
}

template <std::size_t N>
Matrix<N> operator*(const Matrix<N>& a, const Matrix<N>& b) {
    Matrix<N> m{};
    for (std::size_t i = 0; i < N; ++i) {
        for (std::size_t j = 0; j < N; ++j) {
            for (std::size_t k = 0; k < N; ++k)
                m[i][j] += a[i][k] * b[k][j];
        }
    }
    return m;
}

Matrix4 jacobian(const Polynomial& p, const Quaternion& z) {
    Matrix4 m{};
    for (int a = 0; a < 4; ++a) {
        Quaternion direction;
        direction[a] = 1;
        Quaternion column = p.derivative(z, direction);
        for (int i = 0; i < 4; ++i)
            m[i][a] = column[i];
    }
    return m;
}

Matrix4 cycleJacobian(const Polynomial& p, const std::vector<Quaternion>& cycle) {
    Matrix4 m = identityMatrix4();
    for (const Quaternion& z : cycle)
        m = jacobian(p, z) * m;
    return m;
}

template <std::size_t N>
std::array<std::complex<double>, N> eigenvalues(const Matrix<N>& m) {
    ComplexMatrix<N> h = hessenberg<N>(m);
    std::array<Complex, N> result;
    constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
    double scale = 0;
    for (const auto& row : m) {
        for (double v : row)
            scale = std::max(scale, std::abs(v));
    }
    int hi = int(N) - 1, iterations = 0;
    while (hi > 0) {
        int lo = hi;
        for (; lo > 0; --lo) {
            double size = std::abs(h[lo - 1][lo - 1]) + std::abs(h[lo][lo]);
            if (std::abs(h[lo][lo - 1]) <= kEpsilon * (size > 0 ? size : scale)) {
                h[lo][lo - 1] = 0;
                break;
            }
        }
        if (lo == hi || iterations > 200) {  // 200: never reached for 4x4 or 8x8 in practice
            result[hi] = h[hi][hi];
            --hi;
            iterations = 0;
            continue;
        }
        Complex shift = wilkinsonShift<N>(h, hi);
        // An exceptional shift now and then breaks the rare cycles of the plain one.
        if (++iterations % 11 == 0) shift += 0.75 * std::abs(h[hi][hi - 1]);
        qrStep<N>(h, lo, hi, shift);
    }
    result[0] = h[0][0];
    // Keys rounded to 12 digits, so that rounding does not reorder equal moduli (lambda and
    // conj lambda, or mu twice).
    auto key = [](Complex e) {
        auto rounded = [](double v) { return std::round(v * 1e12); };
        return std::array<double, 3>{-rounded(std::abs(e)), -rounded(e.real()), -e.imag()};
    };
    std::sort(result.begin(), result.end(), [&](Complex a, Complex b) { return key(a) < key(b); });
    return result;
}

template <std::size_t N>
bool solve(Matrix<N> m, std::array<double, N> b, std::array<double, N>& x) {
    constexpr int n = int(N);
    double largest = 0;
    for (const auto& row : m) {
        for (double v : row)
            largest = std::max(largest, std::abs(v));
    }
    for (int k = 0; k < n; ++k) {
        int pivot = k;
        for (int i = k + 1; i < n; ++i) {
            if (std::abs(m[i][k]) > std::abs(m[pivot][k])) pivot = i;
        }
        if (!(std::abs(m[pivot][k]) > 1e-14 * largest)) return false;
        std::swap(m[k], m[pivot]);
        std::swap(b[k], b[pivot]);
        for (int i = k + 1; i < n; ++i) {
            double factor = m[i][k] / m[k][k];
            for (int j = k; j < n; ++j)
                m[i][j] -= factor * m[k][j];
            b[i] -= factor * b[k];
        }
    }
    for (int k = n - 1; k >= 0; --k) {
        double sum = b[k];
        for (int j = k + 1; j < n; ++j)
            sum -= m[k][j] * x[j];
        x[k] = sum / m[k][k];
    }
    return true;
}

template Matrix<4> identityMatrix<4>();
template Matrix<8> identityMatrix<8>();
template Matrix<4> operator*(const Matrix<4>&, const Matrix<4>&);
template Matrix<8> operator*(const Matrix<8>&, const Matrix<8>&);
template std::array<std::complex<double>, 4> eigenvalues<4>(const Matrix<4>&);
template std::array<std::complex<double>, 8> eigenvalues<8>(const Matrix<8>&);
template bool solve<4>(Matrix<4>, std::array<double, 4>, std::array<double, 4>&);
template bool solve<8>(Matrix<8>, std::array<double, 8>, std::array<double, 8>&);

}  // namespace quaternia
