// Elements of the algebras of section 2.3 (hypercomplex.h), one type for all of them:
// Element<T, N>, the N components along an algebra's basis e_0 .. e_{N-1}, templated on the
// scalar T (double for the reference, float or a SIMD vector in the lanes, as Embree's
// Vec3<T>). The algebra is not part of the type: its product is its multiplication table,
// sum_ij sign(i, j) a_i b_j e_index(i, j) (MultiplicationTable::multiply), so one element type
// serves every algebra of a dimension, and a table chosen at run time (the scene's algebra).
//
// The quaternion is the 4-dimensional instance, Element<T, 4> = QuaternionT<T> (quaternion.h),
// with named components w, x, y, z and Hamilton's table written out as its operator*, in the
// order the table sums it (Element.QuaternionProductIsHamiltonsTable holds them equal bit for
// bit): the fast path of the scalar reference and of every SIMD lane. The 8-component elements
// (Hypercomplex, hypercomplex.h) hold the 4-component algebras' elements in their first four
// components.
#pragma once

#include <array>

namespace quaternia {

template <typename T, int N>
struct Element : std::array<T, N> {};

}  // namespace quaternia
