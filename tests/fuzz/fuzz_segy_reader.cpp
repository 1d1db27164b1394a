// libFuzzer target: any bytes read as a SEG-Y file either load as a cube or raise VolumeError.
// Anything else (a crash, a sanitizer report, another exception, a hang, an allocation past the
// memory limit) is a bug; each input that found one is kept in tests/fuzz/regressions/ (*.sgy)
// and replayed by segy_bad_input_test.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "volume/segy_reader.h"
#include "volume/volume_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // segyio reads files only: one scratch file per fuzzing process, rewritten for every input.
    static const std::string path = "/tmp/cutaway_fuzz_segy_" + std::to_string(::getpid()) + ".sgy";
    {
        std::ofstream file(path, std::ios::binary | std::ios::trunc);
        file.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    cutaway::volume::SegyReadOptions options;
    options.memory_limit_bytes = std::uint64_t(64) << 20;  // absurd sizes must be refused, not allocated
    try {
        (void)cutaway::volume::load_segy(path, options);
    } catch (const cutaway::volume::VolumeError&) {
    }
    return 0;
}
