#pragma once
// Stage 1 across ranks (SPEC.md section 7). The frustum union keeps the farthest depth at every
// pixel (inverted depth test), so the cut of the whole model is the per-pixel MAX of the ranks'
// cuts; the rear shell (the farthest shell or fault face, or the far plane under a primary) is a
// max too, and so is the cone-field strategies' seed image (the primaries' rear hull). The images
// go through one MPI_Allreduce(MAX) and back into the renderer's textures, so every rank continues
// with the same global cut (or transforms the same seeds).
#include <cstddef>
#include <vector>

#include "gl/gl_objects.h"

namespace cutaway::distributed {

class CutAllreduce {
public:
    CutAllreduce(int width, int height);
    /// Collective. DEPTH32F images of the frame size, each replaced by its per-pixel max over ranks.
    void combine(const std::vector<const gl::Texture*>& images);
    /// Collective: `values` replaced by their sums over ranks (the primaries' centre sums).
    void sum(std::vector<double>& values) const;
    /// Bytes reduced per rank in the last frame (4 per pixel per image, over every combine call).
    std::size_t message_bytes() const { return message_bytes_; }
    /// Starts a frame's tally of message bytes and times (the seeds and the cut may both combine).
    void start_frame();
    /// Wall time of the last MPI_Allreduce alone (ms), without the texture read-back and upload,
    /// and of the barrier before it: the wait for the slowest rank's stage 1 (load imbalance).
    double last_mpi_ms() const { return last_mpi_ms_; }
    double last_wait_ms() const { return last_wait_ms_; }

private:
    int width_, height_;
    std::vector<float> depths_;
    std::size_t message_bytes_ = 0;
    double last_mpi_ms_ = 0;
    double last_wait_ms_ = 0;
};

}  // namespace cutaway::distributed
