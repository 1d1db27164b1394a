#pragma once
// The colour bar drawn into the image: gradient of the colour map, frame, property name, min
// and max values (text from stb_easy_font).
#include <string>

#include "gl/gl_objects.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

struct ColourBarLabel {
    std::string property;  ///< e.g. "PORO"
    float min = 0;
    float max = 1;
};

class ColourBar {
public:
    explicit ColourBar(const gl::ShaderLibrary& shaders);
    /// Draws into `target` (width x height) at the right edge.
    void draw(const gl::Framebuffer& target, int width, int height, const gl::Texture& colour_map,
              const ColourBarLabel& label);

private:
    gl::Program program_;
    gl::VertexArray vertex_array_;
};

}  // namespace cutaway::pipeline
