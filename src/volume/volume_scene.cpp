#include "volume/volume_scene.h"

#include <numeric>

namespace cutaway::volume {

double VolumeScene::occupied_fraction() const {
    if (occupied.empty()) return 0;
    return double(std::accumulate(occupied.begin(), occupied.end(), std::size_t(0))) / double(occupied.size());
}

VolumeScene make_scene(const QuantisedVolume& volume, const TransferTable& table, int block_size, LevelWindow window) {
    VolumeScene scene;
    scene.volume = &volume;
    scene.table = table;
    scene.window = window;
    scene.blocks = build_block_grid(volume, block_size);
    scene.occupied = occupied_blocks(scene.blocks, table);
    return scene;
}

}  // namespace cutaway::volume
