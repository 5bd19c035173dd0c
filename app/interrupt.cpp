#include "interrupt.h"

#include <csignal>
#include <cstring>
#include <stdexcept>

#include <unistd.h>

namespace glint::app {

namespace {

// Signal handlers can reach nothing else: these are the one piece of process-wide state
// in Glint, and only the command line has it.
std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_signal = 0;
// The files that may be half-written, removed on a second signal.
char g_temporaries[2][4096] = {};
struct sigaction g_previous_int, g_previous_term;
std::atomic<bool> g_installed{false};

extern "C" void on_signal(int signo) {
    if (g_stop.load()) {
        // Second signal: leave at once, with nothing half-written under the output's name.
        for (const char* path : g_temporaries)
            if (path[0] != '\0') ::unlink(path);
        ::_exit(128 + signo);
    }
    g_signal = signo;
    g_stop.store(true);
}

}  // namespace

InterruptGuard::InterruptGuard(const std::filesystem::path& image_temporary,
                               const std::filesystem::path& checkpoint_temporary) {
    if (g_installed.exchange(true)) throw std::logic_error("only one InterruptGuard at a time");
    g_stop.store(false);
    g_signal = 0;
    std::strncpy(g_temporaries[0], image_temporary.c_str(), sizeof(g_temporaries[0]) - 1);
    std::strncpy(g_temporaries[1], checkpoint_temporary.c_str(), sizeof(g_temporaries[1]) - 1);
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, &g_previous_int);
    ::sigaction(SIGTERM, &action, &g_previous_term);
}

InterruptGuard::~InterruptGuard() {
    ::sigaction(SIGINT, &g_previous_int, nullptr);
    ::sigaction(SIGTERM, &g_previous_term, nullptr);
    g_temporaries[0][0] = g_temporaries[1][0] = '\0';
    g_installed.store(false);
}

const std::atomic<bool>& InterruptGuard::stop() const { return g_stop; }

int InterruptGuard::signal() const { return g_signal; }

}  // namespace glint::app
