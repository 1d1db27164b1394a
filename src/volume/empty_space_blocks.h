#pragma once
// Empty-space skipping: the volume cut into cubic blocks with the min and max level each block's
// samples can interpolate to; a block is empty for a transfer function when no level in
// [min, max] has opacity. A ray steps over empty blocks without sampling them.
#include <cstdint>
#include <vector>

#include "volume/quantised_volume.h"
#include "volume/transfer_function.h"

namespace cutaway::volume {

/// Block (bi, bx, bt) covers voxel-space positions [b B, (b + 1) B] on each axis (B = block_size,
/// voxel space: voxel v spans [v, v + 1], centre v + 0.5). Its min/max include the one-voxel apron
/// that trilinear interpolation reads at those positions, so every sample taken inside the block
/// lies in [min, max].
struct BlockGrid {
    int block_size = 8;
    CubeDims blocks;                  ///< ceil(dims / block_size) per axis (inlines, crosslines, samples)
    std::vector<std::uint8_t> min;    ///< per block, layout (bi * crosslines + bx) * samples + bt
    std::vector<std::uint8_t> max;
};

/// Min/max levels per block; throws std::invalid_argument if block_size < 1.
BlockGrid build_block_grid(const QuantisedVolume& volume, int block_size);

/// 1 for blocks with any level in [min, max] whose opacity is above 0, else 0 (same layout).
std::vector<std::uint8_t> occupied_blocks(const BlockGrid& grid, const TransferTable& table);

}  // namespace cutaway::volume
