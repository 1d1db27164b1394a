#pragma once
// What every bad-input case shares (issue 18, issue 47): a scratch directory per test with an
// out/ folder for outputs, the `cutaway` program run as a user runs it, and the checks of the
// contract: exit code 2 with a message naming what was wrong, inputs unchanged, and nothing left
// in out/ (neither an output nor a temporary partial file).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cutaway_process.h"

namespace cutaway::testing {

namespace fs = std::filesystem;

// AddressSanitizer's shadow memory and quarantine multiply a process's resident memory, so the
// peak-memory bounds hold only for the plain build (the exit codes and messages are checked in both).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kMeasureMemory = false;
#else
constexpr bool kMeasureMemory = true;
#endif

// What `cutaway` itself holds before it reads any input: the program, its libraries (Mesa, segyio,
// CGAL-free but GL-linked) and the C++ runtime. Measured at about 25 MiB for `cutaway --help`.
constexpr double kBaselineRssMb = 64;

constexpr const char* kTinyGrid =
    "SPECGRID\n 2 2 1 1 F /\n"
    "COORD\n 0 0 0 0 0 1  1 0 0 1 0 1  2 0 0 2 0 1\n"
    " 0 1 0 0 1 1  1 1 0 1 1 1  2 1 0 2 1 1\n"
    " 0 2 0 0 2 1  1 2 0 1 2 1  2 2 0 2 2 1 /\n"
    "ZCORN\n 16*0 16*1 /\n"
    "PORO\n 0.1 0.2 0.3 0.4 /\n"
    "FACIES\n 1 2 1 2 /\n";

/// A trace's inline and crossline numbers.
struct TraceLines {
    int inline_number = 0;
    int crossline_number = 0;
};

/// Trace `t` of a 2 x 2 survey (inlines 1-2, crosslines 1-2).
inline TraceLines two_by_two(int t) { return {1 + t / 2, 1 + t % 2}; }

/// A big-endian SEG-Y file of `traces` traces at `lines` (default 2 x 2) of `samples` IEEE floats
/// (values from `sample`), with the binary header's sample count and format fields set to
/// `samples_field` and `format_field`.
inline std::string segy_bytes(int samples_field, int format_field, int samples, float (*sample)(int trace, int k),
                              int traces = 4, TraceLines (*lines)(int trace) = two_by_two) {
    std::string bytes(3600, '\0');
    const auto put16 = [&bytes](std::size_t at, int v) {
        bytes[at] = char((v >> 8) & 0xFF);
        bytes[at + 1] = char(v & 0xFF);
    };
    put16(3216, 4000);          // sample interval, microseconds (bytes 3217-3218)
    put16(3220, samples_field);  // samples per trace (bytes 3221-3222)
    put16(3224, format_field);  // 5: IEEE float (bytes 3225-3226)
    for (int t = 0; t < traces; ++t) {
        std::string header(240, '\0');
        const auto put32 = [&header](std::size_t at, std::int32_t v) {
            for (int b = 0; b < 4; ++b) header[at + std::size_t(b)] = char((v >> (24 - 8 * b)) & 0xFF);
        };
        put32(188, lines(t).inline_number);      // inline (byte 189)
        put32(192, lines(t).crossline_number);   // crossline (byte 193)
        header[114] = char((samples >> 8) & 0xFF);
        header[115] = char(samples & 0xFF);
        bytes += header;
        for (int k = 0; k < samples; ++k) {
            const float value = sample(t, k);
            std::uint32_t word = 0;
            std::memcpy(&word, &value, 4);
            for (int b = 0; b < 4; ++b) bytes += char((word >> (24 - 8 * b)) & 0xFF);
        }
    }
    return bytes;
}

class BadInput : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        scratch_ = fs::temp_directory_path() /
                   ("cutaway_bad_input_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(scratch_);
        fs::create_directories(scratch_ / "out");
    }
    void TearDown() override { fs::remove_all(scratch_); }

    fs::path file(const std::string& name, const std::string& text) const {
        const fs::path path = scratch_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }
    std::string out(const std::string& name) const { return (scratch_ / "out" / name).string(); }

    ProcessResult cutaway(const std::vector<std::string>& args, ProcessLimits limits = {}) const {
        return run_process(CUTAWAY_EXE, args, scratch_, limits);
    }

    /// Exit 2 and every fragment in the message; the message is one line plus CLI11's help hint.
    static void expect_refused(const ProcessResult& r, const std::vector<std::string>& fragments) {
        EXPECT_EQ(r.exit_code, 2) << r.err;
        for (const std::string& f : fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "'" << f << "' not in: " << r.err;
    }

    /// COORD of an NX x NY grid of vertical unit pillars at integer x, y (pillar (i, j) at x = i,
    /// y = j): written out in full, as a real grid's is (repeat counts cannot make pillars differ).
    static std::string unit_coord(int nx, int ny) {
        std::string text = "COORD\n";
        text.reserve(std::size_t(nx + 1) * std::size_t(ny + 1) * 24);
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                const std::string x = std::to_string(i), y = std::to_string(j);
                text.append(x).append(" ").append(y).append(" 0 ").append(x).append(" ").append(y).append(" 1\n");
            }
        return text + "/\n";
    }

    /// `inspect` of an NX x NY x NZ grid (unit_coord) whose ZCORN is all zeros for the first half of
    /// its values and all ones for the rest (every layer then differs from the one above half-way,
    /// so the store must switch to the full layout), refused under `limit_gb`; returns the child's result.
    ProcessResult refused_half_zero_zcorn(const std::string& name, int nx, int ny, int nz, const std::string& limit_gb) const {
        const std::size_t half = std::size_t(4) * nx * ny * nz;
        const fs::path grid = file(name, "SPECGRID\n " + std::to_string(nx) + " " + std::to_string(ny) + " " +
                                             std::to_string(nz) + " 1 F /\n" + unit_coord(nx, ny) + "ZCORN\n " +
                                             std::to_string(half) + "*0 " + std::to_string(half) + "*1 /\n");
        ProcessResult r = cutaway({"inspect", grid, "--memory-limit-gb", limit_gb});
        expect_refused(r, {name, "ZCORN", "full layout", "memory limit"});
        std::printf("%s: peak %.0f MiB\n", name.c_str(), r.peak_rss_mb);
        return r;
    }

    /// Nothing was written to out/: neither an output nor a temporary partial file.
    void expect_no_output() const {
        for (const auto& entry : fs::directory_iterator(scratch_ / "out"))
            ADD_FAILURE() << "left behind: " << entry.path();
    }

    /// The bytes of `path` (to compare an input before and after a run: unchanged means equal).
    static std::string contents(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        return bytes.str();
    }

    fs::path scratch_;
};

/// The cases that reach the renderer (EGL on llvmpipe): a 64 x 64 frame, one repetition.
class BadInputGl : public BadInput {
protected:
    std::vector<std::string> render_args(const fs::path& grid) const {
        return {"render", grid.string(), "--size", "64", "64", "--repeat", "1", "--warmup", "0"};
    }
    ProcessResult render(const fs::path& grid, const std::vector<std::string>& more) const {
        std::vector<std::string> args = render_args(grid);
        args.insert(args.end(), more.begin(), more.end());
        return cutaway(args);
    }
};

}  // namespace cutaway::testing
