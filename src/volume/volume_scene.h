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
    LevelWindow window;                       ///< the levels the table's colour scale spans
    BlockGrid blocks;
    std::vector<std::uint8_t> occupied;       ///< per block, 1 where the table gives opacity
    double occupied_fraction() const;
};

/// `window`: the levels `table` spans (for the colour bar; build_transfer_table's settings.window).
VolumeScene make_scene(const QuantisedVolume& volume, const TransferTable& table, int block_size, LevelWindow window = {});

}  // namespace cutaway::volume
