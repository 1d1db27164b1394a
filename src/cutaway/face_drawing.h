#pragma once
// What every pass that draws faces (shaders/common/face.vert) needs set.
#include "cutaway/camera.h"
#include "cutaway/camera_blocks.h"
#include "cutaway/grid_buffers.h"
#include "gl/gl_objects.h"

namespace cutaway::pipeline {

struct FaceDrawContext {
    const GridBuffers& grid;
    const Camera& camera;            ///< the camera drawing (the model camera, or the cut camera for depths)
    const CameraBlocks& cameras;     ///< where `camera` is bound as the view (and the cut) camera
    const gl::Texture* colour_map = nullptr;  ///< null for passes that only write depth
    glm::vec2 value_range{0, 1};     ///< property values at the ends of the colour map
    bool log_scale = false;          ///< map log10 of the values (value_range above 0)
};

/// Binds the context's camera as the view and the cut camera (common/cameras.glsl; a pass that
/// reads another camera's cut binds that one after), sets the face program's other uniforms, binds
/// the grid buffers, the colour map (unit 0), the viewport and uses the program.
void prepare_face_program(const gl::Program& program, const FaceDrawContext& context);

/// cut_surface/seed_geometry.frag's depth encoding, (s - near) / (far - near) of `camera`: plain
/// uniforms, not the view block's planes, because the fragment shader reads them for every
/// fragment: on llvmpipe the cut stage (which draws the rear shell) was slower with the block
/// read there than with these (petra 1080p, medians of 22 and 12 alternating pairs); the blocks
/// read by vertex and compute stages showed no such cost.
void set_depth_encoding(const gl::Program& program, const Camera& camera);

}  // namespace cutaway::pipeline
