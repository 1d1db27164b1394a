#include "cutaway/face_drawing.h"

#include "gl/uniforms.h"

namespace cutaway::pipeline {

void prepare_face_program(const gl::Program& p, const FaceDrawContext& context) {
    const Camera& camera = context.camera;
    context.grid.set_geometry_uniforms(p);
    context.cameras.bind_view(camera);
    context.cameras.bind_cut(camera);
    gl::set_uniform(p, "value_range", context.value_range);
    gl::set_uniform(p, "log_scale", context.log_scale);
    gl::set_uniform(p, "colour_map", 0);
    if (context.colour_map) context.colour_map->bind(0);
    context.grid.bind_geometry();
    glViewport(0, 0, camera.width, camera.height);
    p.use();
}

void set_depth_encoding(const gl::Program& program, const Camera& camera) {
    gl::set_uniform(program, "depth_near", camera.near_plane);
    gl::set_uniform(program, "depth_far", camera.far_plane);
}

}  // namespace cutaway::pipeline
