#include "volume/empty_space_blocks.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cutaway::volume {

namespace {
int block_count(int voxels, int block_size) { return (voxels + block_size - 1) / block_size; }

/// Voxels whose values trilinear interpolation reads anywhere in [b B, (b + 1) B]: one apron voxel
/// each side, clamped to the volume (clamp-to-edge sampling).
std::pair<int, int> voxel_span(int block, int block_size, int voxels) {
    return {std::max(block * block_size - 1, 0), std::min((block + 1) * block_size, voxels - 1)};
}
}  // namespace

BlockGrid build_block_grid(const QuantisedVolume& volume, int block_size) {
    if (block_size < 1) throw std::invalid_argument("empty-space block size " + std::to_string(block_size) + ": expected >= 1");
    BlockGrid grid;
    grid.block_size = block_size;
    const CubeDims& d = volume.dims;
    grid.blocks = {block_count(d.inlines, block_size), block_count(d.crosslines, block_size),
                   block_count(d.samples, block_size)};
    grid.min.assign(grid.blocks.count(), 255);
    grid.max.assign(grid.blocks.count(), 0);
    std::size_t block = 0;
    for (int bi = 0; bi < grid.blocks.inlines; ++bi)
        for (int bx = 0; bx < grid.blocks.crosslines; ++bx)
            for (int bt = 0; bt < grid.blocks.samples; ++bt, ++block) {
                const auto [i0, i1] = voxel_span(bi, block_size, d.inlines);
                const auto [x0, x1] = voxel_span(bx, block_size, d.crosslines);
                const auto [t0, t1] = voxel_span(bt, block_size, d.samples);
                std::uint8_t lo = 255, hi = 0;
                for (int i = i0; i <= i1; ++i)
                    for (int x = x0; x <= x1; ++x) {
                        const std::uint8_t* trace =
                            &volume.levels[(std::size_t(i) * std::size_t(d.crosslines) + std::size_t(x)) * std::size_t(d.samples)];
                        const auto [mn, mx] = std::minmax_element(trace + t0, trace + t1 + 1);
                        lo = std::min(lo, *mn);
                        hi = std::max(hi, *mx);
                    }
                grid.min[block] = lo;
                grid.max[block] = hi;
            }
    return grid;
}

std::vector<std::uint8_t> occupied_blocks(const BlockGrid& grid, const TransferTable& table) {
    // Prefix count of opaque levels: a block is occupied when [min, max] holds one.
    std::array<int, 257> opaque_before{};
    for (std::size_t level = 0; level < 256; ++level)
        opaque_before[level + 1] = opaque_before[level] + (table[level].a > 0 ? 1 : 0);
    std::vector<std::uint8_t> occupied(grid.min.size());
    for (std::size_t b = 0; b < occupied.size(); ++b)
        occupied[b] = opaque_before[std::size_t(grid.max[b]) + 1] - opaque_before[grid.min[b]] > 0 ? 1 : 0;
    return occupied;
}

}  // namespace cutaway::volume
