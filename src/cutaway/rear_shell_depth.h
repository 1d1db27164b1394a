#pragma once
// The farthest shell surface along each pixel ray of the cut camera. The cut never goes past it
// (unless --see-through): where a cut would leave the model through its rear shell, showing the
// background through a hole, it is clamped to just in front of the shell, so the rear shows as
// cut fill (cut_surface/resolve.frag applies the clamp).
// Pixels a primary face covers are left unclamped while the primaries are drawn: there the primary
// itself hides the background, and a clamp could keep a sliver of its neighbours' faces (within
// the clamp's margin of the rear shell) in front of its edge-on side faces, hiding primary pixels.
// With the primaries hidden (--only secondaries) nothing would hide it: the clamp holds there too.
#include "cutaway/camera.h"
#include "cutaway/camera_blocks.h"
#include "cutaway/grid_buffers.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

class RearShellDepth {
public:
    /// `cameras` (kept by reference) binds the cut camera render draws from.
    RearShellDepth(const gl::ShaderLibrary& shaders, const CameraBlocks& cameras, int width, int height);
    /// A depth image of the new size (the programs stay).
    void resize(int width, int height);
    /// Draws the shell and fault faces (a fault face may be partly uncovered, so the model may end
    /// there) from `cut_camera` keeping the farthest: (s - near) / (far - near) of the cut camera
    /// in depth(), 0 where no such face covers the pixel, 1 (the far plane) where a primary does
    /// and `primaries_drawn`.
    void render(const GridBuffers& grid, const Camera& cut_camera, bool primaries_drawn);
    const gl::Texture& depth() const { return depth_; }

private:
    void allocate(int width, int height);

    const CameraBlocks& cameras_;
    gl::Program program_;
    gl::Program primaries_program_;  ///< primary faces at the far plane: no clamp there
    gl::Texture depth_;
    gl::Framebuffer framebuffer_;
};

}  // namespace cutaway::pipeline
