#include "cutaway/post/fullscreen_pass.h"

namespace cutaway::pipeline {

void draw_fullscreen(const gl::Program& program, const gl::Framebuffer& target, int width, int height) {
    target.bind();
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    program.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace cutaway::pipeline
