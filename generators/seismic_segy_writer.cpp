#include "generators/seismic_segy_writer.h"

#include <segyio/segy.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

namespace cutaway::generators {

namespace {

struct SegyCloser {
    void operator()(segy_file* file) const { segy_close(file); }
};
using SegyHandle = std::unique_ptr<segy_file, SegyCloser>;

void check(int rc, const std::filesystem::path& path, const char* what) {
    if (rc != SEGY_OK)
        throw std::runtime_error(path.string() + ": segyio failed to " + what + " (error " + std::to_string(rc) + ")");
}

/// Bytes per sample of the supported formats; 0 for the rest.
int sample_bytes(int format) {
    switch (format) {
        case SEGY_IBM_FLOAT_4_BYTE:
        case SEGY_SIGNED_INTEGER_4_BYTE:
        case SEGY_IEEE_FLOAT_4_BYTE: return 4;
        case SEGY_SIGNED_SHORT_2_BYTE: return 2;
        case SEGY_SIGNED_CHAR_1_BYTE: return 1;
        default: return 0;
    }
}

double integer_scale(const SeismicVolume& volume, int format) {
    const double range = format == SEGY_SIGNED_INTEGER_4_BYTE ? 2147483647.0
                         : format == SEGY_SIGNED_SHORT_2_BYTE ? 32767.0
                                                              : 127.0;
    float peak = 0;
    for (float a : volume.amplitudes) peak = std::max(peak, std::abs(a));
    return peak > 0 ? 0.9 * range / peak : 1.0;
}

template <typename Int>
void store_integers(const float* amplitudes, int count, double scale, char* out) {
    for (int t = 0; t < count; ++t) {
        const Int value = Int(std::lround(double(amplitudes[t]) * scale));
        std::memcpy(out + std::size_t(t) * sizeof(Int), &value, sizeof(Int));
    }
}

/// One trace in native layout, then converted by segyio to the on-disk (big-endian) format.
void encode_trace(const float* amplitudes, int samples, int format, double scale, std::vector<char>& out) {
    switch (format) {
        case SEGY_SIGNED_INTEGER_4_BYTE: store_integers<std::int32_t>(amplitudes, samples, scale, out.data()); break;
        case SEGY_SIGNED_SHORT_2_BYTE: store_integers<std::int16_t>(amplitudes, samples, scale, out.data()); break;
        case SEGY_SIGNED_CHAR_1_BYTE: store_integers<std::int8_t>(amplitudes, samples, scale, out.data()); break;
        default: std::memcpy(out.data(), amplitudes, std::size_t(samples) * sizeof(float));
    }
    segy_from_native(format, samples, out.data());
}

std::string text_header(const SeismicVolume& volume) {
    std::string text(3200, ' ');
    const std::string line = "C 1 CUTAWAY SYNTHETIC SEISMIC " + std::to_string(volume.inlines) + "x" +
                             std::to_string(volume.crosslines) + "x" + std::to_string(volume.samples);
    text.replace(0, line.size(), line);
    return text;
}

}  // namespace

void write_segy(const std::filesystem::path& path, const SeismicVolume& volume, const SegyWriteOptions& options) {
    const int bytes = sample_bytes(options.format);
    if (bytes == 0)
        throw std::invalid_argument("write_segy: format " + std::to_string(options.format) +
                                    " unsupported, expected 1 (IBM), 2 (int32), 3 (int16), 5 (IEEE) or 8 (int8)");
    if (options.offsets < 1) throw std::invalid_argument("write_segy: offsets must be >= 1");
    SegyHandle file(segy_open(path.c_str(), "w+b"));
    if (!file) throw std::runtime_error(path.string() + ": cannot open for writing");
    check(segy_set_format(file.get(), options.format | int(options.little_endian ? SEGY_LSB : SEGY_MSB)), path,
          "set the format");

    const std::set<std::pair<int, int>> missing(options.missing_traces.begin(), options.missing_traces.end());
    const int traces = int(volume.trace_count() - missing.size()) * options.offsets;
    std::string text = text_header(volume);
    check(segy_write_textheader(file.get(), 0, text.c_str()), path, "write the text header");
    char binary[SEGY_BINARY_HEADER_SIZE] = {};
    check(segy_set_bfield(binary, SEGY_BIN_TRACES, std::min(traces, 32767)), path, "set the trace count");
    check(segy_set_bfield(binary, SEGY_BIN_INTERVAL, volume.sample_interval_us), path, "set the interval");
    check(segy_set_bfield(binary, SEGY_BIN_SAMPLES, volume.samples), path, "set the sample count");
    check(segy_set_bfield(binary, SEGY_BIN_FORMAT, options.format), path, "set the format");
    check(segy_set_bfield(binary, SEGY_BIN_SORTING_CODE, 4), path, "set the sorting code");
    check(segy_set_bfield(binary, SEGY_BIN_SEGY_REVISION, 0x0100), path, "set the revision");
    check(segy_write_binheader(file.get(), binary), path, "write the binary header");

    const long trace0 = SEGY_TEXT_HEADER_SIZE + SEGY_BINARY_HEADER_SIZE;
    const int trace_bytes = volume.samples * bytes;
    const double scale = bytes == 4 && options.format != SEGY_SIGNED_INTEGER_4_BYTE ? 1.0 : integer_scale(volume, options.format);
    std::vector<char> data(std::size_t(volume.samples) * 4);
    const int outer = options.crossline_sorted ? volume.crosslines : volume.inlines;
    const int inner = options.crossline_sorted ? volume.inlines : volume.crosslines;
    int traceno = 0;
    for (int a = 0; a < outer; ++a)
        for (int b = 0; b < inner; ++b) {
            const int i = options.crossline_sorted ? b : a, x = options.crossline_sorted ? a : b;
            if (missing.count({i, x})) continue;
            encode_trace(&volume.amplitudes[volume.index(i, x, 0)], volume.samples, options.format, scale, data);
            for (int offset = 1; offset <= options.offsets; ++offset, ++traceno) {
                char header[SEGY_TRACE_HEADER_SIZE] = {};
                segy_set_field(header, SEGY_TR_SEQ_LINE, traceno + 1);
                segy_set_field(header, SEGY_TR_SEQ_FILE, traceno + 1);
                segy_set_field(header, SEGY_TR_OFFSET, offset);
                segy_set_field(header, SEGY_TR_SAMPLE_COUNT, volume.samples);
                segy_set_field(header, SEGY_TR_SAMPLE_INTER, volume.sample_interval_us);
                segy_set_field(header, SEGY_TR_INLINE, volume.first_inline + i);
                segy_set_field(header, SEGY_TR_CROSSLINE, volume.first_crossline + x);
                segy_set_field(header, SEGY_TR_CDP_X, 25 * (volume.first_inline + i));
                segy_set_field(header, SEGY_TR_CDP_Y, 25 * (volume.first_crossline + x));
                check(segy_write_traceheader(file.get(), traceno, header, trace0, trace_bytes), path,
                      "write a trace header");
                check(segy_writetrace(file.get(), traceno, data.data(), trace0, trace_bytes), path, "write a trace");
            }
        }
    check(segy_flush(file.get(), false), path, "flush");
}

}  // namespace cutaway::generators
