#include "cone_field/exact_reference.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>

#include "cone_field/cone_slope.h"

namespace cutaway::cone_field {
namespace {

/// Inclusive pixel rectangle.
struct PixelBox {
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
};

/// Smallest distance along one axis between the intervals [a0, a1] and [b0, b1], pixels.
int axis_gap(int a0, int a1, int b0, int b1) { return std::max({0, b0 - a1, a0 - b1}); }

struct SeedTile {
    PixelBox bounds;          ///< bounding box of the seeds
    double max_depth = 0.0;
    std::vector<Seed> seeds;  ///< deepest first, so a pixel stops at the first seed that cannot win

    double bound_at_gap(double slope, int gap_x, int gap_y) const {
        return cone_height(max_depth, slope, gap_x, gap_y);
    }
};

std::vector<SeedTile> group_seeds_into_tiles(const std::vector<Seed>& seeds, int width, int height, int tile_size) {
    const int tiles_x = (width + tile_size - 1) / tile_size;
    const int tiles_y = (height + tile_size - 1) / tile_size;
    std::vector<SeedTile> grid(std::size_t(tiles_x) * std::size_t(tiles_y));
    for (const Seed& seed : seeds) {
        SeedTile& tile = grid[std::size_t(seed.y / tile_size) * std::size_t(tiles_x) + std::size_t(seed.x / tile_size)];
        if (tile.seeds.empty()) {
            tile.bounds = {seed.x, seed.y, seed.x, seed.y};
            tile.max_depth = seed.depth;
        }
        tile.bounds = {std::min(tile.bounds.x0, seed.x), std::min(tile.bounds.y0, seed.y),
                       std::max(tile.bounds.x1, seed.x), std::max(tile.bounds.y1, seed.y)};
        tile.max_depth = std::max(tile.max_depth, double(seed.depth));
        tile.seeds.push_back(seed);
    }
    std::vector<SeedTile> occupied;
    for (SeedTile& tile : grid) {
        if (tile.seeds.empty()) continue;
        std::sort(tile.seeds.begin(), tile.seeds.end(), [](const Seed& a, const Seed& b) { return a.depth > b.depth; });
        occupied.push_back(std::move(tile));
    }
    return occupied;
}

/// Solves one pixel tile; owns the scratch memory one worker thread reuses from tile to tile.
class PixelTileSolver {
public:
    PixelTileSolver(const std::vector<SeedTile>& seed_tiles, double slope) : seed_tiles_(seed_tiles), slope_(slope) {}

    void solve(const PixelBox& box, FloatImage& cut) {
        collect_candidates(box);
        const int box_width = box.x1 - box.x0 + 1;
        best_.assign(std::size_t(box_width) * std::size_t(box.y1 - box.y0 + 1), 0.0);  // 0: the clamp
        double tile_floor = 0.0;  // smallest best height in the tile
        for (const Candidate& candidate : candidates_) {
            if (candidate.bound <= tile_floor) break;  // sorted: no later tile can win anywhere here
            for (int y = box.y0; y <= box.y1; ++y) {
                for (int x = box.x0; x <= box.x1; ++x) {
                    double& best = best_[std::size_t(y - box.y0) * std::size_t(box_width) + std::size_t(x - box.x0)];
                    improve_pixel(x, y, *candidate.tile, best);
                }
            }
            tile_floor = *std::min_element(best_.begin(), best_.end());
        }
        for (int y = box.y0; y <= box.y1; ++y) {
            for (int x = box.x0; x <= box.x1; ++x) {
                cut.at(x, y) = float(best_[std::size_t(y - box.y0) * std::size_t(box_width) + std::size_t(x - box.x0)]);
            }
        }
    }

    std::uint64_t evaluated_pairs() const { return evaluated_pairs_; }

private:
    struct Candidate {
        double bound;  ///< no height from the tile exceeds this anywhere in the pixel tile
        const SeedTile* tile;
    };

    void collect_candidates(const PixelBox& box) {
        candidates_.clear();
        for (const SeedTile& tile : seed_tiles_) {
            const double bound = tile.bound_at_gap(slope_, axis_gap(box.x0, box.x1, tile.bounds.x0, tile.bounds.x1),
                                                   axis_gap(box.y0, box.y1, tile.bounds.y0, tile.bounds.y1));
            if (bound > 0.0) candidates_.push_back({bound, &tile});
        }
        std::sort(candidates_.begin(), candidates_.end(),
                  [](const Candidate& a, const Candidate& b) { return a.bound > b.bound; });
    }

    void improve_pixel(int x, int y, const SeedTile& tile, double& best) {
        const int gap_x = axis_gap(x, x, tile.bounds.x0, tile.bounds.x1);
        const int gap_y = axis_gap(y, y, tile.bounds.y0, tile.bounds.y1);
        for (const Seed& seed : tile.seeds) {
            if (cone_height(seed.depth, slope_, gap_x, gap_y) <= best) break;  // deepest first: the rest lose too
            ++evaluated_pairs_;
            best = std::max(best, cone_height(seed.depth, slope_, seed.x - x, seed.y - y));
        }
    }

    const std::vector<SeedTile>& seed_tiles_;
    double slope_;
    std::vector<Candidate> candidates_;
    std::vector<double> best_;
    std::uint64_t evaluated_pairs_ = 0;
};

void check_options(const ExactReferenceOptions& options) {
    if (options.thread_count > 1024) {
        throw std::invalid_argument("exact reference: thread count must be at most 1024, got " +
                                    std::to_string(options.thread_count));
    }
    if (options.tile_size < 1 || options.tile_size > 1024) {
        throw std::invalid_argument("exact reference: tile size must lie in 1..1024 pixels, got " +
                                    std::to_string(options.tile_size));
    }
}

}  // namespace

ExactReferenceResult exact_reference_cut(const SeedImage& seeds, double slope_per_pixel,
                                         const ExactReferenceOptions& options) {
    check_slope_per_pixel(slope_per_pixel);
    check_options(options);
    const int width = seeds.width();
    const int height = seeds.height();
    const int tile = options.tile_size;
    const std::vector<SeedTile> seed_tiles = group_seeds_into_tiles(collect_seeds(seeds), width, height, tile);

    const int tiles_x = (width + tile - 1) / tile;
    const int tile_count = tiles_x * ((height + tile - 1) / tile);
    const unsigned wanted = options.thread_count != 0 ? options.thread_count : std::thread::hardware_concurrency();
    ExactReferenceResult result;
    result.cut = FloatImage(width, height);
    result.threads_used = std::clamp(wanted, 1u, unsigned(tile_count));

    std::atomic<int> next_tile{0};
    std::vector<std::uint64_t> pairs_per_thread(result.threads_used, 0);
    auto work = [&](unsigned thread_index) {
        PixelTileSolver solver(seed_tiles, slope_per_pixel);
        for (int t = next_tile++; t < tile_count; t = next_tile++) {
            const int x0 = (t % tiles_x) * tile;
            const int y0 = (t / tiles_x) * tile;
            solver.solve({x0, y0, std::min(x0 + tile, width) - 1, std::min(y0 + tile, height) - 1}, result.cut);
        }
        pairs_per_thread[thread_index] = solver.evaluated_pairs();
    };
    {
        std::vector<std::jthread> workers;  // join when leaving the block, also if starting one throws
        for (unsigned i = 1; i < result.threads_used; ++i) workers.emplace_back(work, i);
        work(0);
    }
    for (const std::uint64_t pairs : pairs_per_thread) result.evaluated_pairs += pairs;
    return result;
}

}  // namespace cutaway::cone_field
