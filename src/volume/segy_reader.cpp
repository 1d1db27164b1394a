#include "volume/segy_reader.h"

#include <segyio/segy.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "io/input_file.h"
#include "io/path_text.h"
#include "volume/volume_error.h"

namespace cutaway::volume {

namespace {

constexpr long kHeadersBytes = SEGY_TEXT_HEADER_SIZE + SEGY_BINARY_HEADER_SIZE;

struct SegyCloser {
    void operator()(segy_file* file) const { segy_close(file); }
};
using SegyHandle = std::unique_ptr<segy_file, SegyCloser>;

/// Format codes SEG-Y rev 2 defines (used to tell the byte order), and the ones we convert.
bool is_known_format(int code) { return code >= 1 && code <= 16 && code != 6 && code != 7; }
bool is_supported_format(int code) {
    return code == SEGY_IBM_FLOAT_4_BYTE || code == SEGY_SIGNED_INTEGER_4_BYTE || code == SEGY_SIGNED_SHORT_2_BYTE ||
           code == SEGY_IEEE_FLOAT_4_BYTE || code == SEGY_SIGNED_CHAR_1_BYTE;
}

std::string format_name(int code) {
    switch (code) {
        case SEGY_IBM_FLOAT_4_BYTE: return "IBM float (1)";
        case SEGY_SIGNED_INTEGER_4_BYTE: return "int32 (2)";
        case SEGY_SIGNED_SHORT_2_BYTE: return "int16 (3)";
        case SEGY_FIXED_POINT_WITH_GAIN_4_BYTE: return "fixed point with gain (4)";
        case SEGY_IEEE_FLOAT_4_BYTE: return "IEEE float (5)";
        case SEGY_SIGNED_CHAR_1_BYTE: return "int8 (8)";
        default: return "code " + std::to_string(code);
    }
}

/// Bytes as MiB with three significant digits ("0.0889 MiB", "715 MiB").
std::string mib_text(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g MiB", double(bytes) / double(1 << 20));
    return text;
}

/// Everything the binary header says about the trace layout.
struct TraceLayout {
    int format = 0;
    bool little_endian = false;
    int samples = 0;
    long trace0 = 0;       ///< byte offset of the first trace header
    int trace_bytes = 0;   ///< data bytes per trace (header excluded)
    long long traces = 0;
};

class SegyLoader {
public:
    SegyLoader(std::filesystem::path path, const SegyReadOptions& options) : path_(std::move(path)), options_(options) {}

    VolumeCube load() {
        open();
        read_layout();
        std::vector<TracePosition> positions = read_positions();
        VolumeCube cube = make_grid(positions);
        read_samples(positions, cube);
        cube.sample_interval_ms = sample_interval_ms();
        return cube;
    }

private:
    struct TracePosition {
        int inline_number = 0;
        int crossline_number = 0;
        int offset = 0;
    };

    /// "PATH: WHERE: expected EXPECTED, found FOUND" (WHERE names the header field, trace or sample).
    [[noreturn]] void fail(const std::string& where, const std::string& expected, const std::string& found) const {
        std::string text = io::shown_path(path_);
        text.append(": ");
        if (!where.empty()) text.append(where).append(": ");
        text.append("expected ").append(expected).append(", found ").append(found);
        throw VolumeError(text);
    }

    void open() {
        if (const std::string found = io::input_file_problem(path_); !found.empty()) fail("", "a SEG-Y file", found);
        std::error_code error;
        file_bytes_ = std::uint64_t(std::filesystem::file_size(path_, error));
        if (error) fail("", "a readable SEG-Y file", "its size unreadable (" + error.message() + ")");
        if (file_bytes_ < std::uint64_t(kHeadersBytes))
            fail("not a SEG-Y file", "the " + std::to_string(kHeadersBytes) + "-byte text and binary headers at least",
                 std::to_string(file_bytes_) + " bytes");
        file_.reset(segy_open(path_.c_str(), "rb"));
        if (!file_) fail("", "a readable SEG-Y file", "one that cannot be opened for reading");
    }

    /// Reads the binary header, trying big-endian first and then little-endian: the byte order
    /// whose format code is a SEG-Y code wins.
    void read_layout() {
        char binary[SEGY_BINARY_HEADER_SIZE];
        if (segy_binheader(file_.get(), binary) != SEGY_OK) fail("binary header", "400 readable bytes", "a read error");
        layout_.format = unsigned_field(segy_format(binary));
        const int big_endian_code = layout_.format;
        if (!is_known_format(layout_.format)) {
            segy_set_format(file_.get(), int(SEGY_IBM_FLOAT_4_BYTE) | int(SEGY_LSB));
            if (segy_binheader(file_.get(), binary) != SEGY_OK) fail("binary header", "400 readable bytes", "a read error");
            layout_.format = unsigned_field(segy_format(binary));
            layout_.little_endian = true;
        }
        if (!is_known_format(layout_.format))
            fail("not a SEG-Y file: binary header field 'format' (bytes 3225-3226)", "a sample format code 1-16",
                 std::to_string(big_endian_code) + " big-endian and " + std::to_string(layout_.format) + " little-endian");
        if (!is_supported_format(layout_.format))
            fail("binary header field 'format' (bytes 3225-3226)",
                 "1 (IBM float), 2 (int32), 3 (int16), 5 (IEEE float) or 8 (int8)",
                 "sample format " + format_name(layout_.format) + ", which is not supported");
        segy_set_format(file_.get(), layout_.format | (layout_.little_endian ? SEGY_LSB : SEGY_MSB));

        layout_.samples = unsigned_field(segy_samples(binary));
        if (layout_.samples <= 0)
            fail("binary header field 'samples' (bytes 3221-3222)", "a positive number of samples per trace",
                 std::to_string(layout_.samples));
        layout_.trace0 = segy_trace0(binary);
        if (layout_.trace0 < kHeadersBytes || std::uint64_t(layout_.trace0) > file_bytes_)
            fail("binary header field 'ext_headers' (bytes 3505-3506)",
                 "the first trace within the file's " + std::to_string(file_bytes_) + " bytes",
                 "it at byte " + std::to_string(layout_.trace0));
        layout_.trace_bytes = segy_trsize(layout_.format, layout_.samples);

        const std::uint64_t trace_section = file_bytes_ - std::uint64_t(layout_.trace0);
        const std::uint64_t record = std::uint64_t(SEGY_TRACE_HEADER_SIZE) + std::uint64_t(layout_.trace_bytes);
        if (trace_section % record != 0)
            fail("truncated or not a whole number of traces",
                 "a multiple of the " + std::to_string(record) + "-byte trace (240-byte header + " +
                     std::to_string(layout_.samples) + " samples of " + format_name(layout_.format) + ")",
                 std::to_string(trace_section) + " bytes after the headers (first trace at byte " +
                     std::to_string(layout_.trace0) + ")");
        layout_.traces = (long long)(trace_section / record);
        if (layout_.traces == 0) fail("", "traces after the headers", "none");
        // Bounded before any per-trace allocation: every sample as a float.
        check_memory(std::uint64_t(layout_.traces) * std::uint64_t(layout_.samples), "the traces");
    }

    /// segyio reads the 2-byte binary header fields as signed: 65535 comes back as -1. SEG-Y
    /// defines the sample count and format code as unsigned.
    static int unsigned_field(int value) { return value & 0xFFFF; }

    /// Refuses `samples` when what a render holds for them exceeds the limit: each sample as a
    /// float, its 8-bit level and the level's copy in the 3D texture (host memory on llvmpipe).
    void check_memory(std::uint64_t samples, const std::string& what) const {
        constexpr std::uint64_t bytes_per_sample = sizeof(float) + 1 + 1;
        const std::uint64_t bytes = samples * bytes_per_sample;
        if (bytes > options_.memory_limit_bytes)
            fail(what, "at most the memory limit of " + mib_text(options_.memory_limit_bytes),
                 mib_text(bytes) + " (6 bytes a sample: float, level, texture; beyond the memory limit)");
    }

    std::vector<TracePosition> read_positions() {
        std::vector<TracePosition> positions(std::size_t(layout_.traces));
        char header[SEGY_TRACE_HEADER_SIZE];
        for (std::size_t t = 0; t < positions.size(); ++t) {
            if (segy_traceheader(file_.get(), int(t), header, layout_.trace0, layout_.trace_bytes) != SEGY_OK)
                fail("trace " + std::to_string(t), "a readable 240-byte header", "a read error");
            std::int32_t value = 0;
            if (segy_get_field(header, options_.inline_byte, &value) != SEGY_OK)
                fail("trace header byte " + std::to_string(options_.inline_byte) + " (inline)", "the first byte of a SEG-Y field",
                     "none starting there");
            positions[t].inline_number = value;
            if (segy_get_field(header, options_.crossline_byte, &value) != SEGY_OK)
                fail("trace header byte " + std::to_string(options_.crossline_byte) + " (crossline)",
                     "the first byte of a SEG-Y field", "none starting there");
            positions[t].crossline_number = value;
            segy_get_field(header, SEGY_TR_OFFSET, &value);
            positions[t].offset = value;
        }
        return positions;
    }

    TraceSorting detect_sorting(const std::vector<TracePosition>& positions) const {
        if (positions.size() == 1) return TraceSorting::single_trace;
        const TracePosition& a = positions[0];
        const TracePosition& b = positions[1];
        if (a.inline_number == b.inline_number && a.crossline_number != b.crossline_number)
            return TraceSorting::inline_major;
        if (a.crossline_number == b.crossline_number && a.inline_number != b.inline_number)
            return TraceSorting::crossline_major;
        return TraceSorting::unsorted;
    }

    /// Two traces at one inline/crossline position: pre-stack when their offsets differ, else
    /// missing line numbers (all 0) or a duplicated trace.
    [[noreturn]] void refuse_shared_position(const TracePosition& first, std::size_t first_index,
                                             const TracePosition& second, std::size_t second_index,
                                             bool any_number) const {
        const std::string where = "traces " + std::to_string(first_index) + " and " + std::to_string(second_index) +
                                  " share inline " + std::to_string(second.inline_number) + " crossline " +
                                  std::to_string(second.crossline_number);
        if (first.offset != second.offset)
            fail("pre-stack data", "a post-stack cube with one trace per inline/crossline",
                 where + " (offsets " + std::to_string(first.offset) + " and " + std::to_string(second.offset) +
                     ", trace header byte 37)");
        if (!any_number)
            fail("trace header bytes " + std::to_string(options_.inline_byte) + " (inline) and " +
                     std::to_string(options_.crossline_byte) + " (crossline)",
                 "survey line numbers", "0 and 0 in every trace");
        fail("duplicate traces", "one trace per inline/crossline", where);
    }

    VolumeCube make_grid(const std::vector<TracePosition>& positions) {
        VolumeCube cube;
        cube.source = path_.string();
        cube.format_name = format_name(layout_.format);
        cube.little_endian = layout_.little_endian;
        cube.null_value = options_.null_value;
        cube.sorting = detect_sorting(positions);

        const bool any_number = std::any_of(positions.begin(), positions.end(), [](const TracePosition& p) {
            return p.inline_number != 0 || p.crossline_number != 0;
        });
        std::map<std::pair<int, int>, std::size_t> first_trace;
        for (std::size_t t = 0; t < positions.size(); ++t) {
            const TracePosition& p = positions[t];
            const auto [it, inserted] = first_trace.emplace(std::pair{p.inline_number, p.crossline_number}, t);
            if (!inserted) refuse_shared_position(positions[it->second], it->second, p, t, any_number);
            cube.inline_numbers.push_back(p.inline_number);
            cube.crossline_numbers.push_back(p.crossline_number);
        }
        for (std::vector<int>* numbers : {&cube.inline_numbers, &cube.crossline_numbers}) {
            std::sort(numbers->begin(), numbers->end());
            numbers->erase(std::unique(numbers->begin(), numbers->end()), numbers->end());
        }
        cube.dims = {int(cube.inline_numbers.size()), int(cube.crossline_numbers.size()), layout_.samples};
        check_memory(std::uint64_t(cube.dims.count()),
                     "the " + std::to_string(cube.dims.inlines) + "x" + std::to_string(cube.dims.crosslines) + "x" +
                         std::to_string(cube.dims.samples) + " cube");
        cube.samples.assign(cube.dims.count(), options_.null_value);
        cube.trace_present.assign(std::size_t(cube.dims.inlines) * std::size_t(cube.dims.crosslines), 0);
        return cube;
    }

    static int index_of(const std::vector<int>& numbers, int number) {
        return int(std::lower_bound(numbers.begin(), numbers.end(), number) - numbers.begin());
    }

    void read_samples(const std::vector<TracePosition>& positions, VolumeCube& cube) {
        std::vector<char> raw(std::size_t(layout_.trace_bytes) + 4);
        for (std::size_t t = 0; t < positions.size(); ++t) {
            if (segy_readtrace(file_.get(), int(t), raw.data(), layout_.trace0, layout_.trace_bytes) != SEGY_OK)
                fail("trace " + std::to_string(t), "readable samples", "a read error");
            segy_to_native(layout_.format, layout_.samples, raw.data());
            const int i = index_of(cube.inline_numbers, positions[t].inline_number);
            const int x = index_of(cube.crossline_numbers, positions[t].crossline_number);
            float* trace = &cube.samples[cube.index(i, x, 0)];
            to_floats(raw.data(), trace);
            refuse_non_finite(trace, t);
            cube.trace_present[std::size_t(i) * std::size_t(cube.dims.crosslines) + std::size_t(x)] = 1;
        }
        for (int i = 0; i < cube.dims.inlines; ++i)
            for (int x = 0; x < cube.dims.crosslines; ++x)
                if (!cube.trace_present[std::size_t(i) * std::size_t(cube.dims.crosslines) + std::size_t(x)])
                    cube.missing_traces.emplace_back(cube.inline_numbers[std::size_t(i)],
                                                     cube.crossline_numbers[std::size_t(x)]);
    }

    /// NaN or infinite amplitudes (IEEE or IBM float formats) have no place on the 256 levels: one
    /// +inf made every other level 0 and the render blank.
    void refuse_non_finite(const float* trace, std::size_t trace_index) const {
        for (int k = 0; k < layout_.samples; ++k)
            if (!std::isfinite(trace[k]))
                fail("trace " + std::to_string(trace_index) + " sample " + std::to_string(k), "a finite amplitude",
                     std::isnan(trace[k]) ? "NaN" : trace[k] > 0 ? "+inf" : "-inf");
    }

    /// Native samples of the file's format (after segy_to_native) to floats.
    void to_floats(const char* native, float* out) const {
        const std::size_t n = std::size_t(layout_.samples);
        switch (layout_.format) {
            case SEGY_SIGNED_INTEGER_4_BYTE: convert<std::int32_t>(native, n, out); break;
            case SEGY_SIGNED_SHORT_2_BYTE: convert<std::int16_t>(native, n, out); break;
            case SEGY_SIGNED_CHAR_1_BYTE: convert<std::int8_t>(native, n, out); break;
            default: std::memcpy(out, native, n * sizeof(float));  // IBM is converted to IEEE by segyio
        }
    }

    template <typename Int>
    static void convert(const char* native, std::size_t n, float* out) {
        for (std::size_t k = 0; k < n; ++k) {
            Int value;
            std::memcpy(&value, native + k * sizeof(Int), sizeof(Int));
            out[k] = float(value);
        }
    }

    double sample_interval_ms() {
        float interval_us = 0;
        // segyio prefers the binary header, then the first trace header; 4 ms when both are 0.
        if (segy_sample_interval(file_.get(), 4000.0f, &interval_us) != SEGY_OK || interval_us <= 0)
            interval_us = 4000.0f;
        return double(interval_us) / 1000.0;
    }

    std::filesystem::path path_;
    SegyReadOptions options_;
    SegyHandle file_;
    std::uint64_t file_bytes_ = 0;
    TraceLayout layout_;
};

}  // namespace

VolumeCube load_segy(const std::filesystem::path& path, const SegyReadOptions& options) {
    return SegyLoader(path, options).load();
}

}  // namespace cutaway::volume
