#pragma once
// A long call (a render) made so that Python stays in charge: the work runs on a thread of
// its own, without the GIL, while the calling thread wakes every 50 ms to let Python handle
// its signals (Ctrl-C raises KeyboardInterrupt: the work is asked to stop, waited for, and
// the exception goes on) and to show progress.

#include <pybind11/pybind11.h>

#include <atomic>
#include <cstdint>
#include <functional>

namespace glint::python {

namespace py = pybind11;

/// What the work reports as it goes (Integrator::ProgressCallback's shape); called from any
/// thread.
using ReportProgress = std::function<void(uint32_t done, uint32_t total)>;

/// Run `work` to its end, or until Python raises (KeyboardInterrupt, or the progress
/// callable's exception): then `stop` is set, the work is waited for and the exception
/// rethrown. `progress`: None, True (a bar on sys.stderr, as `glint render` draws one on its
/// terminal) or a callable taking (done, total). An exception of the work is rethrown here.
void run_interruptibly(const std::function<void(const ReportProgress&, const std::atomic<bool>& stop)>& work,
                       const py::object& progress);

}  // namespace glint::python
