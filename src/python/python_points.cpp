// contains and distance: membership in K_N and the distance estimate at arrays of points, in
// the renderer's SIMD lanes (render/point_queries.h).
#include "python/python_module.h"
#include "quaternia/render/point_queries.h"
#include "quaternia/util/error.h"

namespace quaternia::python {
namespace {

using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The points as rows (N, k); a single point (k,) is one row.
std::pair<size_t, int> shapeOf(const Points& points) {
    if (points.ndim() == 1) return {1, int(points.shape(0))};
    if (points.ndim() != 2)
        throw UserError("points", "points must be an array (N, 3), (N, 4) or (N, 8), got " +
                                      std::to_string(points.ndim()) + " dimensions");
    return {size_t(points.shape(0)), int(points.shape(1))};
}

template <bool kInside>
py::array query(const Scene& scene, const Points& points, std::optional<int> threads,
                const py::object& progress) {
    const auto [count, components] = shapeOf(points);
    const int workers = threadsOf(threads);
    using Out = std::conditional_t<kInside, bool, double>;
    py::array_t<Out> out{py::ssize_t(count)};
    Out* data = out.mutable_data();
    const double* in = points.data();
    const Scene copy = scene;
    runWithoutGil(workers, progress, [&](const WorkOptions& work) {
        if constexpr (kInside) {
            static_assert(sizeof(bool) == 1);
            return queryPoints(copy, in, count, components, reinterpret_cast<uint8_t*>(data),
                               nullptr, work);
        } else {
            return queryPoints(copy, in, count, components, nullptr, data, work);
        }
    });
    if (points.ndim() == 1) return py::array(out.attr("reshape")(py::tuple()));
    return out;
}

}  // namespace

void bindPoints(py::module_& module) {
    module.def("contains", &query<true>, py::arg("scene"), py::arg("points"),
               py::arg("threads") = py::none(), py::kw_only(), py::arg("progress") = py::none(),
               R"(Membership in K_N (fractal.max_iterations) of each point, as the renderer
decides it (its SIMD lanes and render.precision where it marches in them).

points: an array (N, 4) of points of the algebra (N, 8) for the 8-component ones),
or (N, 3) of points of the scene's 3D slice (where the camera's rays run).
Returns a bool array (N,).)");
    module.def("distance", &query<false>, py::arg("scene"), py::arg("points"),
               py::arg("threads") = py::none(), py::kw_only(), py::arg("progress") = py::none(),
               R"(The distance estimate at each point (0 inside K_N): the renderer's estimate,
or the proven lower bound of the algebras whose distance is a Lipschitz bound.
points as for contains; in the 3D slice the distance is the renderer's (scaled
by the slice). Returns a float64 array (N,).)");
}

}  // namespace quaternia::python
