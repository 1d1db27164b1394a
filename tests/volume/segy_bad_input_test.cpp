// Files that are not usable SEG-Y: a clear VolumeError naming the file and the field, never a crash.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "volume/volume_error.h"
#include "volume_test_support.h"

namespace cutaway::test {
namespace {

using volume::load_segy;

/// The message of the VolumeError loading `path` throws (fails the test if none is thrown).
std::string load_error(const std::filesystem::path& path, const volume::SegyReadOptions& options = {}) {
    try {
        load_segy(path, options);
    } catch (const volume::VolumeError& error) {
        return error.what();
    }
    ADD_FAILURE() << path << " was accepted";
    return "";
}

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

/// A valid little cube, then `edit` applied to its bytes.
template <typename Edit>
std::filesystem::path edited_cube(const ScratchDir& dir, const std::string& name, Edit&& edit) {
    const auto path = dir.path() / name;
    generators::write_segy(path, synthetic_volume(3, 3, 16));
    std::string bytes = read_bytes(path);
    edit(bytes);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    return path;
}

void expect_mentions(const std::string& message, std::initializer_list<const char*> parts) {
    for (const char* part : parts) EXPECT_NE(message.find(part), std::string::npos) << "missing '" << part << "' in: " << message;
}

TEST(SegyBadInput, MissingFile) {
    expect_mentions(load_error("/nonexistent/cube.sgy"), {"/nonexistent/cube.sgy", "no such file"});
}

TEST(SegyBadInput, EmptyFileIsShorterThanTheHeaders) {
    const ScratchDir dir = unique_scratch("segy-empty");
    expect_mentions(load_error(dir.write("empty.sgy", "")), {"empty.sgy", "not a SEG-Y file", "0 bytes", "3600"});
}

TEST(SegyBadInput, TextFileIsNotSegy) {
    const ScratchDir dir = unique_scratch("segy-text");
    const auto path = dir.write("notes.sgy", std::string(5000, 'a'));
    expect_mentions(load_error(path), {"notes.sgy", "not a SEG-Y file", "'format' (bytes 3225-3226)"});
}

TEST(SegyBadInput, UnsupportedFormatCodeIsNamed) {
    const ScratchDir dir = unique_scratch("segy-format4");
    const auto path = edited_cube(dir, "format4.sgy", [](std::string& b) { b[3225] = 4; });
    expect_mentions(load_error(path), {"format4.sgy", "fixed point with gain (4)", "not supported"});
}

TEST(SegyBadInput, ZeroSamplesPerTrace) {
    const ScratchDir dir = unique_scratch("segy-zero-samples");
    const auto path = edited_cube(dir, "zero.sgy", [](std::string& b) { b[3220] = b[3221] = 0; });
    expect_mentions(load_error(path), {"zero.sgy", "'samples' (bytes 3221-3222): expected a positive number of samples per trace, found 0"});
}

TEST(SegyBadInput, TruncatedLastTrace) {
    const ScratchDir dir = unique_scratch("segy-truncated");
    const auto path = edited_cube(dir, "cut.sgy", [](std::string& b) { b.resize(b.size() - 10); });
    expect_mentions(load_error(path), {"cut.sgy", "truncated", "304-byte trace"});
}

TEST(SegyBadInput, ExtendedHeadersBeyondTheEnd) {
    const ScratchDir dir = unique_scratch("segy-ext-headers");
    const auto path = edited_cube(dir, "ext.sgy", [](std::string& b) { b[3504] = 0x7f; });
    expect_mentions(load_error(path), {"ext.sgy", "'ext_headers'"});
}

TEST(SegyBadInput, CubeOverTheMemoryLimitIsRefusedBeforeAllocating) {
    const ScratchDir dir = unique_scratch("segy-memory");
    const auto path = edited_cube(dir, "cube.sgy", [](std::string&) {});
    volume::SegyReadOptions options;
    options.memory_limit_bytes = 500;  // the 3x3x16 cube's 144 samples need 864 bytes (6 a sample)
    expect_mentions(load_error(path, options), {"cube.sgy", "expected at most the memory limit of", "beyond the memory limit"});
}

TEST(SegyBadInput, TracesWithoutLineNumbers) {
    const ScratchDir dir = unique_scratch("segy-no-numbers");
    volume::SegyReadOptions options;
    options.inline_byte = 1 + 200;  // an unassigned (zero) trace header field
    options.crossline_byte = 205;
    const auto path = edited_cube(dir, "cube.sgy", [](std::string&) {});
    expect_mentions(load_error(path, options), {"cube.sgy", "expected survey line numbers"});
}

TEST(SegyBadInput, FuzzRegressionsFailCleanlyOrLoad) {
    // Every input fuzz_segy_reader ever crashed on (tests/fuzz/regressions/*.sgy): now a
    // VolumeError or a cube, nothing else, under the fuzzer's memory limit.
    const auto dir = std::filesystem::path(CUTAWAY_SOURCE_DIR) / "tests/fuzz/regressions";
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".sgy") continue;
        SCOPED_TRACE(entry.path().string());
        volume::SegyReadOptions options;
        options.memory_limit_bytes = std::uint64_t(64) << 20;
        try {
            (void)load_segy(entry.path(), options);
        } catch (const volume::VolumeError&) {
        }
    }
}

}  // namespace
}  // namespace cutaway::test
