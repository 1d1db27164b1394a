// Shader watcher: edits, additions in subdirectories and removals each report once.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>

#include "cpu/test_files.h"
#include "viewer/shader_watcher.h"

namespace fs = std::filesystem;

namespace cutaway::viewer {
namespace {

/// A scratch shader tree with one file, named uniquely so parallel test runs do not collide.
class ShaderWatcherTest : public ::testing::Test {
protected:
    ShaderWatcherTest() : dir_("viewer-shaders-" + std::to_string(std::random_device{}())) {
        shader_ = dir_.write("flat.frag", "void main() {}\n");
    }
    test::ScratchDir dir_;
    fs::path shader_;
};

TEST_F(ShaderWatcherTest, NoChangeReportsNothing) {
    ShaderWatcher watcher(dir_.path());
    EXPECT_EQ(watcher.root(), dir_.path());
    EXPECT_FALSE(watcher.poll());
    EXPECT_FALSE(watcher.poll());
}

TEST_F(ShaderWatcherTest, EditReportsOnce) {
    ShaderWatcher watcher(dir_.path());
    const auto written = fs::last_write_time(shader_);
    dir_.write("flat.frag", "void main() { }\n");  // same size: only the time tells
    // +2 s: coarse filesystem clocks could give the rewrite the same time stamp.
    fs::last_write_time(shader_, written + std::chrono::seconds(2));
    EXPECT_TRUE(watcher.poll());
    EXPECT_FALSE(watcher.poll());
}

TEST_F(ShaderWatcherTest, FileAddedInASubdirectoryReports) {
    ShaderWatcher watcher(dir_.path());
    fs::create_directories(dir_.path() / "post");
    dir_.write("post/ssao.frag", "void main() {}\n");
    EXPECT_TRUE(watcher.poll());
    EXPECT_FALSE(watcher.poll());
}

TEST_F(ShaderWatcherTest, RemovalReports) {
    ShaderWatcher watcher(dir_.path());
    fs::remove(shader_);
    EXPECT_TRUE(watcher.poll());
    EXPECT_FALSE(watcher.poll());
}

TEST(ShaderWatcher, MissingRootIsNamed) {
    const fs::path missing = fs::temp_directory_path() / "cutaway-no-such-shader-dir";
    try {
        ShaderWatcher watcher(missing);
        FAIL() << "missing root accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find(missing.string()), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace cutaway::viewer
