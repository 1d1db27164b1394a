#pragma once
// The plain frame's geometry (render --baseline, CutawayRenderer::render_baseline): every exposed
// face (shell, fault, next to an inactive cell: what VTK's surface filter keeps) with its 4
// corners stored once per model, so a plain frame needs no culling pass (the vertex shader drops
// the faces that face away, the clipper what lies outside the view) and its vertices read 4
// positions instead of rebuilding them from pillars and depths. Built on first use: 48 bytes per
// exposed face (visibility/store_face_corners.comp).
#include "cutaway/grid_buffers.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

class ExposedSurface {
public:
    ExposedSurface(const gl::ShaderLibrary& shaders, const GridBuffers& grid, const GridLayout& layout);
    /// Draws the faces with the bound face program (common/face.vert with STORED_CORNERS).
    void draw(const GridBuffers& grid) const;
    std::size_t face_count() const { return faces_.count; }
    std::size_t memory_bytes() const { return faces_.buffer.size_bytes() + corners_.size_bytes(); }

private:
    FaceBuffer faces_;
    gl::Buffer corners_;
    gl::BufferTexture corner_texels_;
};

}  // namespace cutaway::pipeline
