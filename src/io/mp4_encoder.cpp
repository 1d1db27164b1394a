#include "io/mp4_encoder.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "io/output_error.h"
#include "io/staged_file.h"

extern char** environ;

namespace cutaway::io {
namespace {

/// ffmpeg's messages kept for the error: its last lines are the reason.
constexpr std::size_t kept_message_bytes = 4096;

/// The last non-empty line of `text`, or a placeholder.
std::string last_line(const std::string& text) {
    std::size_t end = text.find_last_not_of("\r\n \t");
    if (end == std::string::npos) return "no message";
    const std::size_t start = text.find_last_of('\n', end);
    return text.substr(start == std::string::npos ? 0 : start + 1, end + 1 - (start == std::string::npos ? 0 : start + 1));
}

std::string number(double value) {
    std::string text = std::to_string(value);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text;
}

/// Owns posix_spawn's attribute and file-action objects for one spawn.
struct SpawnSetup {
    posix_spawnattr_t attributes{};
    posix_spawn_file_actions_t actions{};
    SpawnSetup() {
        posix_spawnattr_init(&attributes);
        posix_spawn_file_actions_init(&actions);
    }
    ~SpawnSetup() {
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attributes);
    }
    SpawnSetup(const SpawnSetup&) = delete;
    SpawnSetup& operator=(const SpawnSetup&) = delete;
};

}  // namespace

void require_even_size(int width, int height) {
    if (width <= 0 || height <= 0 || width % 2 || height % 2)
        throw std::invalid_argument("--size: expected an even width and height for H.264 (yuv420p), found " +
                                    std::to_string(width) + " x " + std::to_string(height));
}

Mp4Encoder::Mp4Encoder(std::filesystem::path path, const Mp4Settings& settings)
    : path_(std::move(path)), frame_bytes_(std::size_t(std::max(settings.width, 0)) * std::size_t(std::max(settings.height, 0)) * 4) {
    require_even_size(settings.width, settings.height);
    const std::string size = std::to_string(settings.width) + "x" + std::to_string(settings.height);
    const std::vector<std::string> arguments{
        settings.program, "-hide_banner", "-nostdin", "-loglevel", "error", "-y",
        "-f", "rawvideo", "-pix_fmt", "rgba", "-s", size, "-framerate", number(settings.fps), "-i", "pipe:0",
        "-an", "-c:v", "libx264", "-preset", settings.preset, "-crf", std::to_string(settings.crf),
        "-pix_fmt", "yuv420p", "-movflags", "+faststart", "-f", "mp4",
        // "file:": a path with a colon ("a:b/x.mp4") is still a file, not one of ffmpeg's protocols.
        "file:" + path_.string()};
    std::vector<char*> argv;
    for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);

    // stdin: a socket pair, so a write to an ffmpeg that stopped reading fails with EPIPE
    // (MSG_NOSIGNAL) instead of raising SIGPIPE in the whole process.
    int input[2], messages[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, input) != 0) fail_output(path_, errno);
    if (::pipe2(messages, O_CLOEXEC) != 0) {
        const int error = errno;
        ::close(input[0]);
        ::close(input[1]);
        fail_output(path_, error);
    }
    SpawnSetup setup;
    posix_spawn_file_actions_adddup2(&setup.actions, input[1], STDIN_FILENO);
    posix_spawn_file_actions_addopen(&setup.actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&setup.actions, messages[1], STDERR_FILENO);
    // Its own process group: Ctrl-C reaches cutaway, which ends ffmpeg and removes the partial
    // file. Signals the caller blocks (animate blocks SIGINT while it runs) are unblocked again.
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) sigaddset(&defaults, signal_number);
    posix_spawnattr_setsigmask(&setup.attributes, &none);
    posix_spawnattr_setsigdefault(&setup.attributes, &defaults);
    posix_spawnattr_setpgroup(&setup.attributes, 0);
    posix_spawnattr_setflags(&setup.attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    const int spawned = ::posix_spawnp(&pid_, settings.program.c_str(), &setup.actions, &setup.attributes, argv.data(), environ);
    ::close(input[1]);
    ::close(messages[1]);
    input_fd_ = input[0];
    messages_fd_ = messages[0];
    if (spawned != 0) {
        ::close(input_fd_);
        ::close(messages_fd_);
        throw OutputError(path_.string() + ": expected the " + settings.program +
                          " program on PATH to encode the MP4 (Debian package ffmpeg), found: " + std::strerror(spawned));
    }
    message_reader_ = std::thread([this] { read_messages(); });
    writer_ = std::thread([this] { write_loop(); });
}

Mp4Encoder::~Mp4Encoder() {
    if (finished_) return;
    ::kill(pid_, SIGKILL);  // a blocked write then fails with EPIPE and the writer ends
    wait_for_exit();
}

void Mp4Encoder::read_messages() {
    char buffer[1024];
    for (;;) {
        const ssize_t n = ::read(messages_fd_, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        messages_.append(buffer, std::size_t(n));
        if (messages_.size() > 2 * kept_message_bytes) messages_.erase(0, messages_.size() - kept_message_bytes);
    }
}

void Mp4Encoder::write_loop() {
    for (;;) {
        std::vector<std::uint8_t> frame;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [this] { return pending_ || closing_; });
            if (!pending_) return;
            frame = std::move(*pending_);
        }
        std::size_t sent = 0;
        int error = 0;
        while (sent < frame.size()) {
            const ssize_t n = ::send(input_fd_, frame.data() + sent, frame.size() - sent, MSG_NOSIGNAL);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                error = n < 0 ? errno : EPIPE;
                break;
            }
            sent += std::size_t(n);
        }
        std::lock_guard lock(mutex_);
        pending_.reset();
        if (error) write_error_ = error;
        changed_.notify_all();
        if (error) return;
    }
}

void Mp4Encoder::stop_writer() {
    if (!writer_.joinable()) return;
    {
        std::lock_guard lock(mutex_);
        closing_ = true;
        changed_.notify_all();
    }
    writer_.join();
}

void Mp4Encoder::write_frame(std::vector<std::uint8_t> rgba) {
    if (rgba.size() != frame_bytes_)
        throw std::invalid_argument("video frame: " + std::to_string(rgba.size()) + " bytes, expected " +
                                    std::to_string(frame_bytes_));
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !pending_ || write_error_; });
    if (write_error_) {
        lock.unlock();
        fail("that it stopped taking frames, ");
    }
    pending_ = std::move(rgba);
    changed_.notify_all();
}

int Mp4Encoder::wait_for_exit() {
    if (finished_) return exit_status_;
    stop_writer();
    ::close(input_fd_);  // ffmpeg sees the end of its input, writes the file's index and exits
    message_reader_.join();
    ::close(messages_fd_);
    finished_ = true;
    while (::waitpid(pid_, &exit_status_, 0) < 0 && errno == EINTR) {
    }
    return exit_status_;
}

void Mp4Encoder::fail(const std::string& what) {
    const int status = wait_for_exit();
    const std::string exit_text = WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                                                    : "signal " + std::to_string(WTERMSIG(status));
    throw OutputError(path_.string() + ": expected ffmpeg to write the H.264 MP4, found " + what + exit_text + ": " +
                      last_line(messages_));
}

void Mp4Encoder::finish() {
    stop_writer();
    const bool stopped_reading = write_error_ != 0;
    const int status = wait_for_exit();
    if (stopped_reading || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        fail(stopped_reading ? "that it stopped taking frames, " : "");
}

}  // namespace cutaway::io
