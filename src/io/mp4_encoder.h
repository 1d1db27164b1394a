#pragma once
// An H.264 MP4 that common players open (yuv420p, even sizes), encoded by the `ffmpeg` program
// (Debian package ffmpeg) fed raw RGBA frames on its standard input. ffmpeg is spawned without a
// shell, in its own process group (a terminal's Ctrl-C reaches the caller, which ends it), and its
// stderr is kept for the error message. Frames are handed to a writer thread, so the caller renders
// the next frame while ffmpeg takes the last one.
#include <sys/types.h>

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace cutaway::io {

struct Mp4Settings {
    int width = 0;        ///< pixels, even
    int height = 0;       ///< pixels, even
    double fps = 24;      ///< frames per second of playback
    /// x264's constant rate factor: 18-23 look alike to most eyes; lower is larger and sharper.
    int crf = 20;
    /// x264's speed preset: the encoder shares the machine with the renderer (llvmpipe).
    std::string preset = "veryfast";
    std::string program = "ffmpeg";  ///< looked up on PATH
};

/// Throws std::invalid_argument naming --size unless both sides are positive and even (H.264 in
/// yuv420p keeps one colour sample per 2 x 2 pixels).
void require_even_size(int width, int height);

class Mp4Encoder {
public:
    /// Starts ffmpeg writing `path` (created or replaced; the caller stages it, io::StagedFile).
    /// Throws std::invalid_argument for odd or non-positive sizes, OutputError naming `path` when
    /// ffmpeg cannot be started.
    Mp4Encoder(std::filesystem::path path, const Mp4Settings& settings);
    /// Unless finish() returned: ends ffmpeg (SIGKILL) and waits for it; `path` then holds a
    /// partial file for the caller to remove.
    ~Mp4Encoder();
    Mp4Encoder(const Mp4Encoder&) = delete;
    Mp4Encoder& operator=(const Mp4Encoder&) = delete;

    /// Queues one frame: width x height RGBA pixels, rows top to bottom (gl::RgbaImage). Blocks
    /// while the frame before is still being written. Throws OutputError with ffmpeg's message
    /// once ffmpeg has stopped taking frames.
    void write_frame(std::vector<std::uint8_t> rgba);
    /// Closes ffmpeg's input and waits for it; throws OutputError naming the path with ffmpeg's
    /// last message unless every frame was taken and ffmpeg exited with 0.
    void finish();

private:
    void write_loop();
    void read_messages();
    void stop_writer();
    /// Ends the writer, closes ffmpeg's input, collects its messages and waits: its wait status.
    int wait_for_exit();
    /// Waits for ffmpeg (unless done) and throws OutputError naming the path, `what` went wrong,
    /// ffmpeg's exit and last message.
    [[noreturn]] void fail(const std::string& what);

    std::filesystem::path path_;
    std::size_t frame_bytes_;
    pid_t pid_ = -1;
    int input_fd_ = -1;     ///< our end of ffmpeg's stdin (a socket: sent with MSG_NOSIGNAL, no SIGPIPE)
    int messages_fd_ = -1;  ///< our end of ffmpeg's stderr
    std::string messages_;  ///< ffmpeg's stderr (the last few kB)
    std::thread message_reader_;

    std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<std::vector<std::uint8_t>> pending_;  ///< the frame handed to the writer
    bool closing_ = false;
    int write_error_ = 0;  ///< errno of the failed write (EPIPE: ffmpeg stopped reading)
    std::thread writer_;
    bool finished_ = false;  ///< ffmpeg waited for
    int exit_status_ = 0;    ///< its wait status, once finished_
};

}  // namespace cutaway::io
