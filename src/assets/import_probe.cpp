#include "import_probe.h"

#include "glint/diagnostics.h"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>

// Present only in sanitizer builds (weak, so null otherwise).
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

namespace glint {

namespace {

/// What the child prints (an ai_assert message, say) is kept up to this many bytes.
constexpr std::size_t kMaxChildMessage = 4096;

/// Runs in the child. Never returns.
[[noreturn]] void import_in_child(const std::function<void(Assimp::Importer&)>& import, pid_t parent) {
    // A crash must end this process plainly, for the parent to see it: not through the
    // handlers of a sanitizer or fuzzer (which would report it as the parent's crash), and
    // not through the parent's Ctrl-C handler (the parent decides about interruptions).
    for (int signal : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGPIPE}) std::signal(signal, SIG_DFL);
    for (int signal : {SIGINT, SIGTERM}) std::signal(signal, SIG_IGN);
    // But the child must not outlive the parent: a second Ctrl-C, a timeout or a kill ends both.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(1);  // the parent died before prctl took effect
    // Nor may a crash go through a sanitizer's death callbacks: libFuzzer's would record the
    // input as a crash of its own when assimp corrupts memory here, which is contained.
    if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
    {
        // The scene is freed here too, as the parent will free its own: assimp can overrun a
        // buffer while reading and leave glibc to find the damage only when the scene is
        // deleted (fuzz/regressions/fuzz_ply/assimp_invalid_free_in_scene_destructor.ply).
        Assimp::Importer importer;
        import(importer);
    }
    ::_exit(0);  // no exit handlers, no flushing of the parent's buffered output
}

/// Everything written to `fd` until its end, at most kMaxChildMessage bytes kept.
std::string read_messages(int fd) {
    std::string text;
    std::array<char, 4096> buffer;
    for (;;) {
        const ssize_t n = ::read(fd, buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return text;
        text.append(buffer.data(),
                    std::min(std::size_t(n), kMaxChildMessage - std::min(text.size(), kMaxChildMessage)));
    }
}

std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    return line;
}

}  // namespace

void probe_import(const std::function<void(Assimp::Importer&)>& import, const std::string& context) {
    std::fflush(nullptr);  // or the child would inherit, and print, the parent's pending output
    int messages[2];
    if (::pipe(messages) != 0)
        throw SceneError(context + ": cannot start the importer process: " + std::strerror(errno));
    const pid_t parent = ::getpid();
    const pid_t child = ::fork();
    if (child == 0) {
        ::close(messages[0]);
        ::dup2(messages[1], STDOUT_FILENO);
        ::dup2(messages[1], STDERR_FILENO);
        ::close(messages[1]);
        import_in_child(import, parent);
    }
    ::close(messages[1]);
    if (child < 0) {
        ::close(messages[0]);
        throw SceneError(context + ": cannot start the importer process: " + std::strerror(errno));
    }
    const std::string printed = first_line(read_messages(messages[0]));
    ::close(messages[0]);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0)
        if (errno != EINTR) throw SceneError(context + ": lost the importer process: " + std::strerror(errno));
    // The child ends with status 0 whatever assimp made of the file; anything else (a
    // signal, or a sanitizer's exit status 1) means the import is not safe to repeat here.
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
    const std::string how = WIFSIGNALED(status) ? std::string(::strsignal(WTERMSIG(status)))
                                                : "exit status " + std::to_string(WEXITSTATUS(status));
    throw SceneError(context + ": assimp crashed on this file (" + how + ")" +
                     (printed.empty() ? std::string() : ": " + printed) +
                     "; the file is malformed or uses something assimp cannot read");
}

}  // namespace glint
