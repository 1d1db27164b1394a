// The ffmpeg pipe behind `cutaway animate` (no GL): frames in, an H.264 MP4 out that ffprobe reads,
// and ffmpeg's failures as one OutputError naming the file and ffmpeg's reason.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "io/mp4_encoder.h"
#include "io/output_error.h"

namespace cutaway::io {
namespace {

/// A scratch directory per test, removed after it.
class Mp4Encoder : public ::testing::Test {
protected:
    void SetUp() override { std::filesystem::create_directories(dir_); }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::filesystem::path scratch(const std::string& name) const { return dir_ / name; }

private:
    std::filesystem::path dir_ =
        std::filesystem::temp_directory_path() / ("cutaway_mp4_test_" + std::to_string(::getpid()));
};

/// ffprobe's answer for the first video stream's `field` (frames counted by decoding).
std::string probe(const std::filesystem::path& file, const std::string& field) {
    const std::string command = "ffprobe -v error -select_streams v:0 -count_frames -show_entries stream=" + field +
                                " -of default=noprint_wrappers=1:nokey=1 '" + file.string() + "'";
    std::string out;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        char buffer[256];
        while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
        ::pclose(pipe);
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
    return out;
}

Mp4Settings small() {
    Mp4Settings settings;
    settings.width = 64;
    settings.height = 48;
    return settings;
}

std::vector<std::uint8_t> frame(std::uint8_t shade) { return std::vector<std::uint8_t>(64 * 48 * 4, shade); }

TEST_F(Mp4Encoder, WritesAnH264Yuv420pFileWithEveryFrame) {
    const std::filesystem::path path = scratch("five.mp4");
    io::Mp4Encoder encoder(path, small());
    for (int i = 0; i < 5; ++i) encoder.write_frame(frame(std::uint8_t(40 * i)));
    encoder.finish();
    EXPECT_EQ(probe(path, "codec_name"), "h264");
    EXPECT_EQ(probe(path, "pix_fmt"), "yuv420p");
    EXPECT_EQ(probe(path, "nb_read_frames"), "5");
}

TEST_F(Mp4Encoder, RefusesOddSizesAndWrongFrames) {
    Mp4Settings odd = small();
    odd.width = 63;
    EXPECT_THROW(io::Mp4Encoder(scratch("odd.mp4"), odd), std::invalid_argument);
    io::Mp4Encoder encoder(scratch("short.mp4"), small());
    EXPECT_THROW(encoder.write_frame(std::vector<std::uint8_t>(10)), std::invalid_argument);
}

TEST_F(Mp4Encoder, MissingProgramNamesThePackage) {
    Mp4Settings settings = small();
    settings.program = "cutaway-test-no-such-ffmpeg";
    try {
        io::Mp4Encoder encoder(scratch("none.mp4"), settings);
        FAIL() << "no exception";
    } catch (const OutputError& e) {
        EXPECT_NE(std::string(e.what()).find("Debian package ffmpeg"), std::string::npos) << e.what();
    }
}

TEST_F(Mp4Encoder, FfmpegFailureCarriesItsReason) {
    // ffmpeg cannot open a file in a missing directory: it stops taking frames or exits non-zero,
    // and the message names the path and ffmpeg's reason.
    const std::filesystem::path path = scratch("missing-dir") / "x.mp4";
    try {
        io::Mp4Encoder encoder(path, small());
        for (int i = 0; i < 50; ++i) encoder.write_frame(frame(0));
        encoder.finish();
        FAIL() << "no exception";
    } catch (const OutputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path.string() + ": expected ffmpeg to write the H.264 MP4, found ", 0), 0u) << message;
        EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    }
}

TEST_F(Mp4Encoder, AnUnfinishedEncoderEndsFfmpegAtOnce) {
    const auto started = std::chrono::steady_clock::now();
    {
        io::Mp4Encoder encoder(scratch("abandoned.mp4"), small());
        encoder.write_frame(frame(0));
    }
    // SIGKILL, not waiting for ffmpeg to encode and exit on its own: well under a second.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 5.0);
}

}  // namespace
}  // namespace cutaway::io
