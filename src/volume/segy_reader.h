#pragma once
// SEG-Y post-stack cubes through segyio's C API. Sample formats IBM float, IEEE float, int32,
// int16 and int8 in either byte order (detected from the binary header's format code); traces
// placed by their inline/crossline header numbers, so inline- and crossline-sorted files read the
// same; positions with no trace (irregular survey) filled with the null value and listed.
#include <cstdint>
#include <filesystem>

#include "volume/volume_cube.h"

namespace cutaway::volume {

struct SegyReadOptions {
    float null_value = 0;             ///< written into missing traces
    int inline_byte = 189;            ///< trace header byte of the inline number (SEG-Y rev 1)
    int crossline_byte = 193;         ///< trace header byte of the crossline number
    /// Refuse cubes whose samples would need more than this many bytes (6 a sample: the float,
    /// its 8-bit level and the 3D texture's copy), before allocating.
    std::uint64_t memory_limit_bytes = std::uint64_t(4) << 30;
};

/// Reads the cube in `path`. Throws VolumeError naming the file and the field for: a missing or
/// unreadable file, a file too short for the headers, an unknown or unsupported sample format, a
/// bad sample count, a truncated trace section, a pre-stack file (several traces per position),
/// traces without line numbers, or a cube over the memory limit.
VolumeCube load_segy(const std::filesystem::path& path, const SegyReadOptions& options = {});

}  // namespace cutaway::volume
