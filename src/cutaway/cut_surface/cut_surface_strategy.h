#pragma once
// Stage 1 behind one interface: a strategy turns the primary cells into the cut surface (the
// rear hull of what must be removed), written into CutTargets. Stages 2 and 3 read only
// CutTargets, so every strategy's images are comparable.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cutaway/active_cell_rank.h"
#include "cutaway/camera.h"
#include "cutaway/camera_blocks.h"
#include "cone_field/cone_image.h"
#include "cutaway/frame_settings.h"
#include "cutaway/frame_targets.h"
#include "cutaway/grid_buffers.h"
#include "gl/shader_library.h"
#include "grid/grid_dims.h"

namespace cutaway::pipeline {

class OpeningCut;

/// The primary selection as the CPU holds it, for strategies that precompute per selection.
struct PrimarySelection {
    const std::vector<std::uint8_t>* flags = nullptr;              ///< one per Eclipse cell
    const ActiveCellRank* compact_of_cell = nullptr;  ///< Eclipse -> compact index of an active cell
    grid::GridDims dims;
    std::uint64_t generation = 0;  ///< changes whenever the selection does
};

struct CutSurfaceInputs {
    const GridBuffers& grid;
    const Camera& cut_camera;
    const CameraBlocks& cameras;  ///< binds the cut camera for passes that draw faces from it
    /// Half the full apertures (FrameSettings): each wall's lean from the view ray through the
    /// primary's edge, radians 0..pi/2, measured in the eye's horizontal (x, depth) and vertical
    /// (y, depth) planes; pi/2: flat walls.
    float wall_angle_h_rad = 0;
    float wall_angle_v_rad = 0;
    float back_margin = 0;     ///< render units behind each primary's far side
    float rim_depth = 0;       ///< depth (along the view axis) where nothing lies in front: walls stop
    /// Depth along the view axis of the primaries' centroid (mean of their cell centres), at least
    /// the near plane: where the cone-field strategies match their cones to the frustum walls
    /// (cone_field_strategy.h). Known on the CPU without reading anything back.
    float cone_reference_depth = 0;
    SeedSource seeds = SeedSource::boxes;  ///< for the strategies that start from seeds
    PrimarySelection selection = {};
    /// Set when the frame runs across several renderers (cutaway_renderer.h FrameHooks): replaces
    /// the seed image (cut_seeds.h, DEPTH32F, larger = farther) by the per-pixel max over all of
    /// them before any transform, so every renderer transforms the same seeds.
    std::function<void(const gl::Texture& seeds)> combine_seeds = {};
    /// Cells whose cut opens or closes over an animation's frames (opening_cut.h), or null: the
    /// seed strategies add them to their seeds, so their cut grows with the strategy's own slope
    /// and equals the strategy's cut of the cell once it is a primary.
    const OpeningCut* openings = nullptr;
};

class CutSurfaceStrategy {
public:
    virtual ~CutSurfaceStrategy() = default;
    /// Writes the cut's depth image into targets.depth, which the caller cleared to 0 ("nothing
    /// cut"): (s - near) / (far - near) of the cut camera, s the depth along its view axis.
    /// The pipeline then rebuilds normals and the rear-shell clamp (cut_resolve.h).
    virtual void render(const CutSurfaceInputs& inputs, const CutTargets& targets) = 0;
    /// Bytes the last render() read back from the GPU (0 for a strategy that runs on the GPU).
    virtual std::size_t readback_bytes() const { return 0; }
};

/// A cone-field cut on the CPU: seeds (depth units) and slope m (depth units per pixel) to the cut
/// surface (cone_field/).
using ConeFieldCut = std::function<cone_field::FloatImage(const cone_field::SeedImage&, double slope_per_pixel)>;

struct CutSurfaceEntry {
    std::string name;
    std::string device;  ///< where its cut is computed: "gpu", or "cpu" (seeds read back, result uploaded)
    std::string why;     ///< why it runs there
    std::function<std::unique_ptr<CutSurfaceStrategy>(const gl::ShaderLibrary&)> make;
    /// For a cone-field strategy: the CPU function computing the same cut from the same seeds and
    /// slope (itself, for one on the CPU), the reference tests compare with. Empty otherwise.
    ConeFieldCut cpu_reference = {};
    /// Builds its cut from the primary flags on the CPU (frustum-clusters groups them into boxes):
    /// the renderer reads a GPU selection back for it, once per selection. The others read nothing.
    bool selection_on_cpu = false;
};

}  // namespace cutaway::pipeline
