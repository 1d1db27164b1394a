#pragma once
// bench_cutaway's own flags (taken out of argv before Google Benchmark sees it). Each list is one
// axis of the benchmark product; the defaults keep the product small (the paper's Table 1 setup).
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <string>
#include <vector>

namespace cutaway::bench {

struct CutawayBenchOptions {
    std::vector<std::string> presets{"zaphirus", "petra", "opharine", "sapphire"};
    std::vector<double> fractions{0.01};           ///< primary fraction of active cells
    std::vector<std::string> strategies{"all"};    ///< registry names, or "all"
    std::vector<std::string> borders{"raycast"};   ///< raycast|threshold
    std::vector<int> mean_filters{9};              ///< k x k, 0 = off
    std::vector<std::string> draws{"visible"};     ///< stage 2 faces: visible|all-faces
    /// Full opening angles (horizontal = vertical), degrees 0..180, as `cutaway render --aperture`
    /// takes them; empty = each pose's own aperture along the camera path (camera_path.h).
    std::vector<int> apertures;
    /// Strategies whose CPU reference BM_cpu_reference times ("all" = every chosen GPU strategy
    /// that has one, "none" = no BM_cpu_reference).
    std::vector<std::string> cpu_references{"all"};
    int width = 1920, height = 1080;
    int poses = 8;                                 ///< camera path length (camera_path.h)
    bool per_pose = false;                         ///< one benchmark per pose instead of the whole path
    bool ssao = true;                              ///< SSAO in every frame (--ssao=0: off, for stage-1 sweeps)
    bool baseline = true;                          ///< time the plain frame of the same poses too (--baseline=0: skip)
    int warmup = 1;                                ///< untimed passes over the path first
    int repeat = 1;                                ///< timed passes over the path (each pose repeat times)
};

inline std::vector<std::string> split_list(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');)
        if (!item.empty()) items.push_back(item);
    return items;
}

template <class T>
std::vector<T> parse_list(const std::string& flag, const std::string& text) {
    std::vector<T> values;
    for (const std::string& item : split_list(text)) {
        std::size_t used = 0;
        try {
            if constexpr (std::is_same_v<T, int>) values.push_back(std::stoi(item, &used));
            else values.push_back(std::stod(item, &used));
        } catch (const std::logic_error&) {
            used = 0;
        }
        if (used != item.size()) throw std::invalid_argument(flag + ": '" + item + "' is not a number");
    }
    return values;
}

inline const char* usage_text() {
    return "bench_cutaway flags (besides Google Benchmark's):\n"
           "  --presets=zaphirus,petra,opharine,sapphire   --fractions=0.01   --strategies=all|auto|NAME,...\n"
           "  --borders=raycast[,threshold]   --mean_filters=9[,0,33]   --size=1920x1080\n"
           "  --draws=visible[,all-faces]   --apertures=60[,120] (default: the camera path's own)\n"
           "  --cpu_references=all|none|NAME,...   --ssao=1   --baseline=1\n"
           "  --poses=8   --per_pose   --warmup=1   --repeat=1\n";
}

/// Removes the flags above from argv (argc updated); throws std::invalid_argument on bad values.
inline CutawayBenchOptions take_bench_options(int& argc, char** argv) {
    CutawayBenchOptions options;
    int kept = 1;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        const auto eq = arg.find('=');
        const std::string flag = arg.substr(0, eq);
        const std::string value = eq == std::string::npos ? "" : arg.substr(eq + 1);
        if (flag == "--presets") options.presets = split_list(value);
        else if (flag == "--fractions") options.fractions = parse_list<double>(flag, value);
        else if (flag == "--strategies") options.strategies = split_list(value);
        else if (flag == "--borders") options.borders = split_list(value);
        else if (flag == "--draws") options.draws = split_list(value);
        else if (flag == "--mean_filters") options.mean_filters = parse_list<int>(flag, value);
        else if (flag == "--apertures") options.apertures = parse_list<int>(flag, value);
        else if (flag == "--cpu_references") options.cpu_references = split_list(value);
        else if (flag == "--poses") options.poses = parse_list<int>(flag, value).at(0);
        else if (flag == "--warmup") options.warmup = parse_list<int>(flag, value).at(0);
        else if (flag == "--repeat") options.repeat = parse_list<int>(flag, value).at(0);
        else if (flag == "--per_pose") options.per_pose = true;
        else if (flag == "--ssao") options.ssao = parse_list<int>(flag, value).at(0) != 0;
        else if (flag == "--baseline") options.baseline = parse_list<int>(flag, value).at(0) != 0;
        else if (flag == "--size") {
            const auto x = value.find('x');
            if (x == std::string::npos) throw std::invalid_argument("--size: expected WxH, got '" + value + "'");
            options.width = parse_list<int>(flag, value.substr(0, x)).at(0);
            options.height = parse_list<int>(flag, value.substr(x + 1)).at(0);
        } else {
            argv[kept++] = argv[a];
        }
    }
    argc = kept;
    if (options.poses < 1 || options.repeat < 1) throw std::invalid_argument("--poses, --repeat: at least 1");
    for (const int aperture : options.apertures)
        if (aperture < 0 || aperture > 180)
            throw std::invalid_argument("--apertures: expected full opening angles 0..180 degrees, got " + std::to_string(aperture));
    for (const std::string& border : options.borders)
        if (border != "raycast" && border != "threshold")
            throw std::invalid_argument("--borders: expected raycast or threshold, got '" + border + "'");
    for (const std::string& draw : options.draws)
        if (draw != "visible" && draw != "all-faces")
            throw std::invalid_argument("--draws: expected visible or all-faces, got '" + draw + "'");
    return options;
}

}  // namespace cutaway::bench
