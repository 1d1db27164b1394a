#pragma once
// A regular post-stack seismic cube: inline x crossline x time samples as floats, with the line
// numbers and sample interval of the survey it came from.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cutaway::volume {

/// Cube size in samples.
struct CubeDims {
    int inlines = 0;
    int crosslines = 0;
    int samples = 0;  ///< time samples per trace
    std::size_t count() const { return std::size_t(inlines) * std::size_t(crosslines) * std::size_t(samples); }
};

/// How the traces were ordered in the file.
/// `unsorted`: neither line number is constant between the first two traces (traces are placed by
/// their header numbers either way).
enum class TraceSorting { inline_major, crossline_major, single_trace, unsorted };
const char* sorting_name(TraceSorting sorting);

struct VolumeCube {
    CubeDims dims;
    std::vector<int> inline_numbers;     ///< survey number of each inline index, ascending
    std::vector<int> crossline_numbers;  ///< survey number of each crossline index, ascending
    double sample_interval_ms = 0;       ///< time between samples, milliseconds
    /// Sample (inline i, crossline x, time t) at `samples[(i * crosslines + x) * dims.samples + t]`.
    std::vector<float> samples;
    float null_value = 0;  ///< value written into missing traces
    /// (inline number, crossline number) of every grid position with no trace in the file.
    std::vector<std::pair<int, int>> missing_traces;
    std::vector<std::uint8_t> trace_present;  ///< inlines*crosslines flags, 1 where a trace was read

    // Provenance, for reports.
    std::string source;             ///< file path
    std::string format_name;        ///< e.g. "IBM float (1)"
    bool little_endian = false;
    TraceSorting sorting = TraceSorting::inline_major;

    std::size_t index(int inline_index, int crossline_index, int sample) const {
        return (std::size_t(inline_index) * std::size_t(dims.crosslines) + std::size_t(crossline_index)) *
                   std::size_t(dims.samples) + std::size_t(sample);
    }
    float at(int inline_index, int crossline_index, int sample) const {
        return samples[index(inline_index, crossline_index, sample)];
    }
};

/// Smallest and largest sample of the traces present (nulls of missing traces left out).
struct ValueRange {
    float min = 0;
    float max = 0;
};
ValueRange present_value_range(const VolumeCube& cube);

}  // namespace cutaway::volume
