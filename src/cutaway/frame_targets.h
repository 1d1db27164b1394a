#pragma once
// Render targets of one frame size.
#include <memory>

#include "gl/gl_objects.h"

namespace cutaway::pipeline {

/// Stage 1 output: R32F depth along the cut camera's axis (clamped at the rear shell; 0 = nothing
/// cut), an R8 flag where the cut is clamped at the rear shell, and the depth buffer of the union
/// (cleared to 0, GL_GREATER). SPEC.md's textures of cut positions and normals are not kept: the
/// passes that shade cut fill rebuild a pixel's normal from its depth and its 4 neighbours'
/// (common/cut_lookup.glsl cut_normal_at). The positions cost 16 bytes per pixel, the normals 12
/// more, and with them stage 2's cut test read a 16-byte texel per fragment instead of 4.
///
/// The mean-filtered cut has no targets of its own: the resolve reads the filter's output buffer
/// (MeanFilter::filter) and writes this surface and flag, which stage 2 reads either way (a
/// filtered copy of the targets cost 4 bytes per pixel and two copies of the depth image).
struct CutTargets {
    CutTargets(int width, int height);
    gl::Texture surface;
    gl::Texture rear_clamp;  ///< R8: 1 where the cut is the clamp in front of the rear shell
    gl::Texture depth;
    gl::Framebuffer framebuffer;
    /// Clears to "nothing cut" (depth 0 everywhere).
    void clear() const;
};

/// secondary/nearest_face.frag's output: 1 + the nearest kept face's index per pixel (R32UI),
/// with the scene's depth.
struct NearestFaceTarget {
    explicit NearestFaceTarget(const gl::Texture& scene_depth);
    gl::Texture index;
    gl::Framebuffer framebuffer;
    void clear() const;
};

/// Stages 2 and 3: lit colour, eye-space normal + linear depth, cell id + flags, depth.
/// colour and face_plane hold something only where id is not 0 (clear() leaves them as they were).
struct SceneTargets {
    SceneTargets(int width, int height);
    gl::Texture colour;        ///< RGBA8, where id is not 0
    gl::Texture normal_depth;  ///< RG32UI: eye-space normal, linear depth (0 = background), shaders/common/packed_normal.glsl
    gl::Texture id;            ///< RG32UI: compact cell + 1 (0 = background), flags
    gl::Texture face_plane;    ///< RG32UI where id is not 0: world normal of the visible secondary face and 1 + face class (0 on primaries; deferred: the linear depth), packed as normal_depth
    gl::Texture depth;         ///< DEPTH32F
    gl::Framebuffer framebuffer;
    /// Stage 2's first pass on the visible path with --stage2-passes 2 (allocated at its first
    /// use: 4 bytes per pixel a one-pass frame does not need).
    const NearestFaceTarget& nearest_face() const;
    /// Stage 2's draw with --stage2-passes deferred (secondary.frag, DEFERRED): id and
    /// face_plane only (16 of the 28 bytes per pixel the shaded draw writes per fragment), depth.
    gl::Framebuffer deferred_framebuffer;
    /// The plain frame's (`--baseline`): colour, id and depth only (secondary/plain.frag), so a
    /// frame without a cut writes 12 bytes per pixel instead of the G-buffer's 32.
    gl::Framebuffer plain_framebuffer;
    gl::Texture shell_depth;   ///< R32F linear depth of the uncut shell (contours)
    gl::Texture shell_depth_buffer;
    gl::Framebuffer shell_framebuffer;
    void clear() const;
    void clear_plain() const;

private:
    mutable std::unique_ptr<NearestFaceTarget> nearest_face_;
};

/// Post-processing: ambient occlusion factor and the final RGBA8 image.
struct PostTargets {
    PostTargets(int width, int height);
    /// RG32F: factor and the linear depth of its pixel; at half resolution (FrameSettings::
    /// ssao_half_resolution) only the top-left quarter is written (post/ssao.comp).
    gl::Texture ambient;
    gl::Texture final_colour;  ///< RGBA8
    gl::Framebuffer final_framebuffer;
};

}  // namespace cutaway::pipeline
