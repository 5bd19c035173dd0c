#include "isolated_import.h"

#include "glint/diagnostics.h"

#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <utility>

// Present only in sanitizer builds (weak, so null otherwise).
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

namespace glint {

namespace {

/// What the child prints (an ai_assert message, say) is kept up to this many bytes.
constexpr std::size_t kMaxChildMessage = 4096;

/// A file descriptor closed when it goes out of scope.
class OwnedFd {
public:
    explicit OwnedFd(int fd) : fd_(fd) {}
    OwnedFd(const OwnedFd&) = delete;
    OwnedFd& operator=(const OwnedFd&) = delete;
    ~OwnedFd() {
        if (fd_ >= 0) ::close(fd_);
    }
    [[nodiscard]] int get() const { return fd_; }

private:
    int fd_;
};

/// Write all of `bytes` to `fd`; false on failure.
bool write_all(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        bytes.remove_prefix(std::size_t(n));
    }
    return true;
}

/// Runs in the child: the result of `work` to `result_fd`, 'K' and its bytes or 'E' and the
/// message of what it threw. Never returns.
[[noreturn]] void work_in_child(const std::function<std::string()>& work, const std::string& context, int result_fd,
                                pid_t parent) {
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
    // The tag and the bytes are written apart: joined, a large mesh would be copied once more.
    char tag = 'K';
    std::string result;
    try {
        result = work();
    } catch (const SceneError& e) {
        tag = 'E';
        result = e.what();
    } catch (const std::exception& e) {
        tag = 'E';
        result = context + ": " + e.what();
    }
    if (!write_all(result_fd, std::string_view(&tag, 1)) || !write_all(result_fd, result)) {
        std::fprintf(stderr, "cannot hand the meshes back: %s\n", std::strerror(errno));
        ::_exit(2);
    }
    ::_exit(0);  // no exit handlers, no flushing of the parent's buffered output
}

/// What the child wrote to `fd`, a memory file: its tag (the first byte, 0 for none) and the
/// bytes after it, read straight into place (no copy that drops the tag afterwards).
std::pair<char, std::vector<char>> read_result(int fd, const std::string& context) {
    struct stat info {};
    if (::fstat(fd, &info) != 0)
        throw SceneError(context + ": lost what the importer process read: " + std::strerror(errno));
    if (info.st_size == 0) return {'\0', {}};
    auto read_at = [&](char* out, std::size_t size, std::size_t offset) {
        for (std::size_t at = 0; at < size;) {
            const ssize_t n = ::pread(fd, out + at, size - at, off_t(offset + at));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) throw SceneError(context + ": lost what the importer process read: " + std::strerror(errno));
            at += std::size_t(n);
        }
    };
    char tag = '\0';
    read_at(&tag, 1, 0);
    std::vector<char> bytes(std::size_t(info.st_size) - 1);
    read_at(bytes.data(), bytes.size(), 1);
    return {tag, std::move(bytes)};
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

std::vector<char> run_isolated(const std::function<std::string()>& work, const std::string& context) {
    std::fflush(nullptr);  // or the child would inherit, and print, the parent's pending output
    // The result goes to a memory file, not a pipe: the child can write all of it without
    // waiting for the parent, which reads the child's messages until they end.
    const OwnedFd result(::memfd_create("glint-import", MFD_CLOEXEC));
    int pipe_ends[2];
    if (result.get() < 0 || ::pipe(pipe_ends) != 0)
        throw SceneError(context + ": cannot start the importer process: " + std::strerror(errno));
    const OwnedFd messages(pipe_ends[0]);
    const pid_t parent = ::getpid();
    const pid_t child = ::fork();
    if (child == 0) {
        ::dup2(pipe_ends[1], STDOUT_FILENO);
        ::dup2(pipe_ends[1], STDERR_FILENO);
        ::close(pipe_ends[1]);
        work_in_child(work, context, result.get(), parent);
    }
    ::close(pipe_ends[1]);
    if (child < 0) throw SceneError(context + ": cannot start the importer process: " + std::strerror(errno));
    const std::string printed = first_line(read_messages(messages.get()));
    int status = 0;
    while (::waitpid(child, &status, 0) < 0)
        if (errno != EINTR) throw SceneError(context + ": lost the importer process: " + std::strerror(errno));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        const std::string how = WIFSIGNALED(status) ? std::string(::strsignal(WTERMSIG(status)))
                                                    : "exit status " + std::to_string(WEXITSTATUS(status));
        throw SceneError(context + ": assimp crashed on this file (" + how + ")" +
                         (printed.empty() ? std::string() : ": " + printed) +
                         "; the file is malformed or uses something assimp cannot read");
    }
    auto [tag, bytes] = read_result(result.get(), context);
    if (tag == 'E') throw SceneError(std::string(bytes.begin(), bytes.end()));
    if (tag != 'K') throw SceneError(context + ": the importer process handed back nothing readable");
    return std::move(bytes);
}

}  // namespace glint
