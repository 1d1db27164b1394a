#pragma once
// Writes a SeismicVolume as SEG-Y (rev 1 layout, 3600-byte headers) through segyio's C API, in any
// sample format segyio converts and either byte order. Options make the odd files the reader must
// handle: crossline sorting, missing traces (irregular survey), several offsets (pre-stack).
#include <filesystem>
#include <utility>
#include <vector>

#include "generators/seismic_volume.h"

namespace cutaway::generators {

struct SegyWriteOptions {
    /// SEG-Y format code: 1 IBM float, 2 int32, 3 int16, 5 IEEE float, 8 int8.
    int format = 5;
    bool little_endian = false;
    bool crossline_sorted = false;  ///< traces ordered crossline-major (inline numbers vary fastest)
    /// (inline index, crossline index) pairs left out of the file: an irregular survey.
    std::vector<std::pair<int, int>> missing_traces;
    /// Traces per (inline, crossline) position, with offsets 1..n; above 1 makes a pre-stack file.
    int offsets = 1;
};

/// Writes `volume` to `path`; integer formats scale amplitudes so the largest |amplitude| maps to
/// 90% of the type's range. Throws std::runtime_error naming the path on any segyio failure and
/// std::invalid_argument for an unsupported format.
void write_segy(const std::filesystem::path& path, const SeismicVolume& volume, const SegyWriteOptions& options = {});

}  // namespace cutaway::generators
