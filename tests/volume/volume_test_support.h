#pragma once
// Shared helpers of the volume tests: the shared SEG-Y files, and small synthetic cubes written
// through the generator's SEG-Y writer and read back through the reader under test.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "cpu/test_files.h"
#include "generators/seismic_model.h"
#include "generators/seismic_segy_writer.h"
#include "volume/segy_reader.h"

namespace cutaway::test {

/// A scratch folder whose name carries the process id: ctest -j runs each test in its own process,
/// and suites with the same folder name must not remove each other's files.
inline ScratchDir unique_scratch(const std::string& name) { return ScratchDir(name + "-" + std::to_string(::getpid())); }

inline std::filesystem::path segy_file(const std::string& name) { return shared_data() / "segy" / name; }

/// A small synthetic cube (inlines x crosslines x samples, fixed seed) with the generator's
/// defaults otherwise.
inline generators::SeismicVolume synthetic_volume(int inlines, int crosslines, int samples, std::uint64_t seed = 7) {
    generators::SeismicParameters p;
    p.inlines = inlines;
    p.crosslines = crosslines;
    p.samples = samples;
    p.seed = seed;
    p.max_throw_samples = std::min(12.0, samples / 4.0);
    return generators::generate_seismic(p);
}

/// `volume` written to `dir/name` with `options`, then loaded.
inline volume::VolumeCube write_and_load(const ScratchDir& dir, const std::string& name,
                                         const generators::SeismicVolume& volume,
                                         const generators::SegyWriteOptions& options = {},
                                         const volume::SegyReadOptions& read = {}) {
    const auto path = dir.path() / name;
    generators::write_segy(path, volume, options);
    return volume::load_segy(path, read);
}

}  // namespace cutaway::test
