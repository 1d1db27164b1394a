// libFuzzer target: any bytes given to the GRDECL reader either build a grid or raise GrdeclError.
// Anything else (a crash, a sanitizer report, another exception, a hang) is a bug; each input that
// found one is kept in tests/fuzz/regressions/ and replayed by grdecl_bad_input_test.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "grid/grdecl_reader.h"
#include "grid/grid_summary.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    cutaway::grid::GrdeclReadOptions options;
    options.memory_limit_bytes = std::size_t(64) << 20;  // absurd sizes must be refused, not allocated
    options.allow_include = false;
    cutaway::grid::GrdeclReader reader(options);
    try {
        reader.read_text(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz-input");
        const cutaway::grid::CornerPointGrid grid = reader.finish();
        (void)cutaway::grid::summarize(grid);  // geometry on whatever was accepted must not crash
    } catch (const cutaway::grid::GrdeclError&) {
    }
    return 0;
}
