#pragma once
// Stage 1 across ranks (SPEC.md section 7). The frustum union keeps the farthest depth at every
// pixel (inverted depth test), so the cut of the whole model is the per-pixel MAX of the ranks'
// cuts; the rear shell (the farthest shell or fault face, or the far plane under a primary) is a
// max too. Both images go through one MPI_Allreduce(MAX) and back into the renderer's textures,
// so every rank continues with the same global cut.
#include <cstddef>
#include <vector>

#include "gl/gl_objects.h"

namespace cutaway::distributed {

class CutAllreduce {
public:
    CutAllreduce(int width, int height);
    /// Collective. `cut_depth`, `rear_shell` (null: see-through): DEPTH32F images of the frame size.
    void combine(const gl::Texture& cut_depth, const gl::Texture* rear_shell);
    /// Bytes of the reduced message per rank and frame (4 per pixel per image).
    std::size_t message_bytes() const { return message_bytes_; }
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
