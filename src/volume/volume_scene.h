#pragma once
// What both casters draw: the quantised volume, its transfer table and the min/max blocks the
// table leaves empty.
#include <cstdint>
#include <vector>

#include "volume/empty_space_blocks.h"
#include "volume/quantised_volume.h"
#include "volume/transfer_function.h"

namespace cutaway::volume {

struct VolumeScene {
    const QuantisedVolume* volume = nullptr;  ///< not owned; outlives the scene
    TransferTable table;
    BlockGrid blocks;
    std::vector<std::uint8_t> occupied;       ///< per block, 1 where the table gives opacity
    double occupied_fraction() const;
};

VolumeScene make_scene(const QuantisedVolume& volume, const TransferTable& table, int block_size);

}  // namespace cutaway::volume
