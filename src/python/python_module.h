// What the Python module's sources share (module.cpp registers them): the scene's values in and
// out of Python, the exceptions, NumPy arrays that own the library's buffers, and long calls run
// without the GIL that Ctrl-C interrupts. The module is a front end like the CLI: it owns the
// boundary (exceptions, the GIL), the library below it never prints and never exits.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene.h"
#include "quaternia/util/memory_budget.h"
#include "quaternia/util/parallel.h"

namespace quaternia::python {

namespace py = pybind11;

void bindErrors(py::module_& module);
void bindScene(py::module_& module);
void bindImages(py::module_& module);
void bindPoints(py::module_& module);
void bindMeshes(py::module_& module);
void bindReports(py::module_& module);

// A Python value as `parameter` takes it (checkedValue then checks it): bool, int, float, str,
// or a sequence (a NumPy array too) of numbers, nested for a parameter of groups (slice.axes).
ParameterValue parameterValueOf(const Parameter& parameter, py::handle value);
// The value as Python reads it: float, int, bool, str, or a list of floats (of lists, for a
// parameter of groups).
py::object pythonValueOf(const Parameter& parameter, const ParameterValue& value);

// The scene with the keyword overrides of a call (width=..., samples=...) set through the table,
// so that a bad one is the same ValueError, naming its key, as scene[key] = value raises.
Scene withOverrides(const Scene& scene,
                    const std::vector<std::pair<const char*, std::optional<int64_t>>>& values);

// Raise the module's exceptions (the GIL held): UnknownKeyError (a KeyError and a ValueError),
// MemoryError and OSError, each with the library's one-line message.
[[noreturn]] void raiseUnknownKey(const std::string& message);
[[noreturn]] void raiseMemoryError(const std::string& message);
[[noreturn]] void raiseOSError(const std::string& message);
// Throws UnknownKeyError for a name the table does not have, with the nearest one.
const Parameter& parameterNamed(const std::string& name);

// A call's threads= (None or 0: every core), checked: ValueError naming `threads` outside
// [0, 1024].
int threadsOf(std::optional<int> threads);
// The budget a call's memory_budget names ("512M", "8G", "unlimited"; by default "auto", the
// memory this process can still take).
MemoryBudget memoryBudgetOf(const std::optional<std::string>& budget, int threads);
// Checks `bytes` against `budget` ("512M", "8G", "auto" (the default: the memory this process
// can still take), "unlimited") before any work; MemoryError naming `key` if it does not fit.
void requireMemoryOrRaise(uint64_t bytes, const std::optional<std::string>& budget, int threads,
                          const std::string& key, const std::string& what,
                          const std::string& advice);

// A NumPy array over a buffer the library filled, without a copy: the vector moves into the
// array's owner (a capsule), freed when the last view of it goes.
template <class Element, class Vector>
py::array_t<Element> adoptArray(Vector&& buffer, std::vector<py::ssize_t> shape) {
    using Owned = std::decay_t<Vector>;
    auto* owned = new Owned(std::forward<Vector>(buffer));
    py::capsule owner(owned, [](void* p) { delete static_cast<Owned*>(p); });
    return py::array_t<Element>(std::move(shape), reinterpret_cast<const Element*>(owned->data()),
                                owner);
}

// Runs work(options) without the GIL on a thread of its own, while the calling thread looks,
// every kPollInterval, for Python's signals (Ctrl-C raises KeyboardInterrupt there, which
// cancels the work through options.cancel) and hands the progress (a fraction) to `progress`
// if it is callable. Python runs only on the calling thread, with the GIL. An exception of the
// work, of the signal handler or of the callback is raised once the work has stopped.
inline constexpr std::chrono::milliseconds kPollInterval{20};

template <class Work>
auto runWithoutGil(int threads, const py::object& progress, Work work) {
    using Result = decltype(work(WorkOptions{}));
    std::atomic<bool> cancel{false};
    std::atomic<double> fraction{-1.0};
    WorkOptions options;
    options.threads = threads;
    options.cancel = &cancel;
    if (!progress.is_none()) options.progress = [&](double f) { fraction.store(f); };
    std::optional<Result> result;
    std::exception_ptr failure;
    std::optional<py::error_already_set> pythonError;
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    double reported = -1.0;  // the last fraction handed to `progress`
    {
        py::gil_scoped_release release;
        std::thread worker([&] {
            try {
                result.emplace(work(options));
            } catch (...) {
                failure = std::current_exception();
            }
            std::lock_guard<std::mutex> lock(mutex);
            done = true;
            finished.notify_all();
        });
        for (;;) {
            {
                std::unique_lock<std::mutex> lock(mutex);
                if (finished.wait_for(lock, kPollInterval, [&] { return done; })) break;
            }
            if (pythonError) continue;  // cancelled: waiting for the work to stop
            py::gil_scoped_acquire acquire;
            if (PyErr_CheckSignals() != 0) {
                pythonError.emplace();  // takes the error (KeyboardInterrupt) out of Python
                cancel.store(true);
                continue;
            }
            const double now = fraction.load();
            if (!progress.is_none() && now != reported) {
                reported = now;
                try {
                    progress(now);
                } catch (py::error_already_set& error) {
                    pythonError.emplace(std::move(error));
                    cancel.store(true);
                }
            }
        }
        worker.join();
    }
    if (pythonError) throw std::move(*pythonError);
    if (failure) std::rethrow_exception(failure);
    if (!progress.is_none() && reported != 1.0) progress(1.0);
    return std::move(*result);
}

}  // namespace quaternia::python
