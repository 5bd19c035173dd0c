#include "interruptible_call.h"

#include "glint/util/progress_text.h"

#include <chrono>
#include <exception>
#include <future>
#include <string>
#include <thread>

namespace glint::python {

namespace {

/// The largest `done` reported (tiles finish on many threads, their reports in any order).
class ProgressState {
public:
    void report(uint32_t done, uint32_t total) {
        total_.store(total);
        uint32_t seen = done_.load();
        while (seen < done && !done_.compare_exchange_weak(seen, done)) {
        }
    }
    [[nodiscard]] uint32_t done() const { return done_.load(); }
    [[nodiscard]] uint32_t total() const { return total_.load(); }

private:
    std::atomic<uint32_t> done_{0}, total_{0};
};

/// Shows a ProgressState the way `progress` asks, with the GIL held.
class ProgressDisplay {
public:
    explicit ProgressDisplay(const py::object& progress) {
        if (progress.is_none() || py::isinstance<py::bool_>(progress)) {
            bar_ = !progress.is_none() && progress.cast<bool>();
        } else if (PyCallable_Check(progress.ptr())) {
            callable_ = progress;
        } else {
            throw py::type_error("progress: expected True, False or a callable taking (done, total); got " +
                                 std::string(py::repr(progress)));
        }
    }

    void show(const ProgressState& state) {
        const uint32_t done = state.done(), total = state.total();
        if (total == 0 || done == shown_) return;
        shown_ = done;
        if (!callable_.is_none()) callable_(done, total);
        const auto now = std::chrono::steady_clock::now();
        if (!bar_ || (done != total && now - drawn_ < std::chrono::milliseconds(100))) return;
        drawn_ = now;
        write("\r" + progress_text(double(done) / double(total), std::chrono::duration<double>(now - start_).count()) +
              " ");
    }

    /// Clears the bar's line.
    void finish() {
        if (bar_) write("\r" + std::string(80, ' ') + "\r");
    }

private:
    static void write(const std::string& text) {
        // Python's sys.stderr, which a notebook shows under the cell (C++'s stderr it does not).
        const py::object stderr_stream = py::module_::import("sys").attr("stderr");
        stderr_stream.attr("write")(text);
        stderr_stream.attr("flush")();
    }

    bool bar_ = false;
    py::object callable_ = py::none();
    uint32_t shown_ = 0;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), drawn_;
};

}  // namespace

void run_interruptibly(const std::function<void(const ReportProgress&, const std::atomic<bool>& stop)>& work,
                       const py::object& progress) {
    ProgressDisplay display(progress);
    ProgressState state;
    std::atomic<bool> stop{false};
    std::promise<void> finished;
    std::future<void> result = finished.get_future();
    std::thread worker([&] {
        try {
            work([&](uint32_t done, uint32_t total) { state.report(done, total); }, stop);
            finished.set_value();
        } catch (...) {
            finished.set_exception(std::current_exception());
        }
    });
    const auto join = [&] {
        const py::gil_scoped_release release;
        worker.join();
    };
    try {
        for (bool done = false; !done;) {
            {
                const py::gil_scoped_release release;
                done = result.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready;
            }
            // Runs Python's signal handlers (the main thread only): SIGINT's raises
            // KeyboardInterrupt, which pybind11 carries as error_already_set.
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            display.show(state);
        }
    } catch (...) {
        stop.store(true);
        join();
        display.finish();
        throw;
    }
    join();
    display.finish();
    result.get();
}

}  // namespace glint::python
