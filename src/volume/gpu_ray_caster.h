#pragma once
// The paper's GPU ray caster (needs a current GL 4.5 context): pass 1 draws the cube's back faces
// into an exit-point texture, pass 2 draws its front faces and marches each pixel's ray in the
// fragment shader (shaders/volume/ray_cast.frag). Optional parts are shader variants.
#include <array>

#include "gl/shader_library.h"
#include "gl/stage_timer.h"
#include "volume/cast_result.h"
#include "volume/ray_cast_settings.h"
#include "volume/texture_3d.h"
#include "volume/volume_scene.h"

namespace cutaway::volume {

class GpuRayCaster {
public:
    /// Uploads the scene's volume (R8 3D texture, trilinear), table and block occupancy. `scene`
    /// (and the one given to set_transfer) must outlive the caster; so must `shaders`.
    GpuRayCaster(const gl::ShaderLibrary& shaders, const VolumeScene& scene);

    /// Replaces the table and occupancy (same volume, same block size).
    void set_transfer(const VolumeScene& scene);

    /// One frame. Timed stages in `timer`: "exit_points", "ray_cast", "readback" (fenced wall clock
    /// and GL query each); the colour bar is drawn after readback when the settings ask for it.
    CastResult render(const RayCastSettings& settings, gl::StageTimer& timer);

private:
    struct Targets {
        int width = 0, height = 0;
        gl::Texture exit_points, colour, counts;
        gl::Framebuffer exit_framebuffer, ray_framebuffer;
    };
    const gl::Program& ray_program(const RayCastSettings& settings);
    void ensure_targets(int width, int height);

    const gl::ShaderLibrary& shaders_;
    const VolumeScene* scene_;
    Texture3D volume_levels_;
    Texture3D occupied_blocks_;
    gl::Texture transfer_table_;
    gl::VertexArray empty_vertex_array_;
    gl::Program exit_program_;
    std::array<gl::Program, 16> ray_programs_;  ///< by variant bits (see ray_program)
    Targets targets_;
};

}  // namespace cutaway::volume
