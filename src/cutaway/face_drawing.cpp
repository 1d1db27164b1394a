#include "cutaway/face_drawing.h"

#include "gl/uniforms.h"

namespace cutaway::pipeline {

void prepare_face_program(const gl::Program& p, const FaceDrawContext& context) {
    const Camera& camera = context.camera;
    context.grid.set_geometry_uniforms(p);
    gl::set_uniform(p, "view_projection", camera.view_projection());
    gl::set_uniform(p, "model_view", camera.view);
    gl::set_uniform(p, "eye_position", camera.eye);
    gl::set_uniform(p, "light_eye", camera.eye);
    gl::set_uniform(p, "viewport_size", glm::vec2(float(camera.width), float(camera.height)));
    gl::set_uniform(p, "value_range", context.value_range);
    gl::set_uniform(p, "log_scale", context.log_scale);
    gl::set_uniform(p, "colour_map", 0);
    if (context.colour_map) context.colour_map->bind(0);
    gl::set_uniform(p, "cut_view", camera.view);
    gl::set_uniform(p, "cut_view_projection", camera.view_projection());
    context.grid.bind_geometry();
    glViewport(0, 0, camera.width, camera.height);
    p.use();
}

}  // namespace cutaway::pipeline
