#pragma once
// Sort-last compositing of the ranks' G-buffers with IceT (Z-buffer mode, icetCompositeImage on
// pre-rendered buffers; IceT needs no GL context of its own here). Every channel the screen-space
// passes read is composited with the same window depth, so every channel of a pixel comes from
// the same rank:
//   composite 1, RGBA32F: the eye-space normal's two 16-bit halves as packed in the normal_depth
//     target (shaders/common/packed_normal.glsl; exact in float), 0, linear depth (SSAO's input);
//   composite 2, RGBA32F holding exact integers below 2^24: colour R + 256 G + 65536 B, the
//     whole-model Eclipse id + 1 in two 16-bit halves, and the pixel flags;
//   the uncut shell's linear depth (contours) has its own depth: MPI_Reduce(MIN) at rank 0.
// Rank 0 (IceT's display rank) gets the result written back into its SceneTargets, and the
// screen-space passes run there once. This header does not include mpi.h or IceT.h.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "cutaway/frame_targets.h"

namespace cutaway::distributed {

class SceneCompositor {
public:
    /// Collective: an IceT context on a duplicate of MPI_COMM_WORLD, one tile of width x height
    /// displayed by rank 0, radix-k single-image compositing.
    SceneCompositor(int width, int height);
    ~SceneCompositor();
    SceneCompositor(const SceneCompositor&) = delete;
    SceneCompositor& operator=(const SceneCompositor&) = delete;

    /// Collective. `whole_ids`: this rank's whole-model Eclipse id + 1 per pixel (0: none), rows
    /// bottom to top. At rank 0 the composited frame replaces `scene`'s colour, normal_depth, id
    /// (whole-model Eclipse id + 1, flags), depth and shell_depth; returns true there.
    bool composite(const pipeline::SceneTargets& scene, const std::vector<std::uint32_t>& whole_ids);
    /// Whether this rank displays the composited frame (rank 0): it runs the screen-space passes.
    bool displays() const;
    /// Rank 0: the last composited frame's whole-model Eclipse id + 1 per pixel.
    const std::vector<std::uint32_t>& composited_ids() const;

    /// Bytes IceT sent from this rank in the last composite (both passes; ICET_BYTES_SENT), and the
    /// bytes this rank sent for the shell-depth reduction.
    std::size_t icet_bytes_sent() const;
    std::size_t reduce_bytes_sent() const;
    /// Wall time of the last frame's IceT calls and shell reduction alone (ms), and of the barrier
    /// before them: the wait for the slowest rank's stages 2 and 3 (load imbalance).
    double last_exchange_ms() const;
    double last_wait_ms() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace cutaway::distributed
