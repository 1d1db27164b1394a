#pragma once
// Paths of the shared real data and scratch files for the CPU tests.
#include <filesystem>
#include <fstream>
#include <string>

namespace cutaway::test {

inline std::filesystem::path shared_data() { return CUTAWAY_SHARED_DATA; }
inline std::filesystem::path reek_grid() { return shared_data() / "grdecl/reek/reek_sim_grid.grdecl"; }
inline std::filesystem::path reek_poro() { return shared_data() / "grdecl/reek/reek_sim_poro.grdecl"; }

/// A fresh directory under the system temp dir, removed when the object goes.
class ScratchDir {
public:
    explicit ScratchDir(const std::string& name)
        : path_(std::filesystem::temp_directory_path() / ("cutaway-test-" + name)) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const auto file = path_ / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace cutaway::test
