#pragma once
// What every pass that draws faces (shaders/common/face.vert) needs set.
#include "cutaway/camera.h"
#include "cutaway/grid_buffers.h"
#include "gl/gl_objects.h"

namespace cutaway::pipeline {

struct FaceDrawContext {
    const GridBuffers& grid;
    const Camera& camera;            ///< the model camera
    const gl::Texture* colour_map = nullptr;  ///< null for passes that only write depth
    glm::vec2 value_range{0, 1};     ///< property values at the ends of the colour map
    bool log_scale = false;          ///< map log10 of the values (value_range above 0)
};

/// Sets the face program's uniforms, binds the grid buffers, the colour map (unit 0), the
/// viewport and uses the program.
void prepare_face_program(const gl::Program& program, const FaceDrawContext& context);

}  // namespace cutaway::pipeline
