#pragma once
// GPU copies of a GridLayout and of the face lists of one primary selection (std430 buffers,
// bound at the binding points declared in shaders/common/grid.glsl and face.vert).
#include <glm/glm.hpp>

#include "cutaway/grid_layout.h"
#include "gl/gl_objects.h"

namespace cutaway::pipeline {

/// Binding points shared with the shaders.
enum BufferBinding : unsigned { pillars_binding = 0, corner_depths_binding = 1, cells_binding = 2,
                                faces_binding = 3, values_binding = 4, primary_cells_binding = 5 };

struct FaceBuffer {
    gl::Buffer buffer;
    std::size_t count = 0;
    static FaceBuffer from(const std::vector<std::uint32_t>& records);
};

class GridBuffers {
public:
    GridBuffers(const GridLayout& layout, const grid::GridDims& dims, const ModelFrame& frame);

    /// One value per active cell (compact order).
    void set_values(const std::vector<float>& compact_values);
    void set_selection(const FaceLists& lists);

    /// Binds pillars, corner depths, cells and values.
    void bind_geometry() const;
    /// Draws `faces` as 2 triangles each with the bound face program.
    static void draw_faces(const FaceBuffer& faces);

    glm::uvec2 grid_size() const { return grid_size_; }
    const ModelFrame& frame() const { return frame_; }
    const FaceBuffer& secondary_faces() const { return secondary_; }
    const FaceBuffer& primary_faces() const { return primary_; }
    const FaceBuffer& primary_cells() const { return primary_cells_; }
    const FaceBuffer& shell_faces() const { return shell_; }
    const FaceBuffer& all_faces() const { return all_; }

private:
    glm::uvec2 grid_size_;
    ModelFrame frame_;
    gl::Buffer pillars_, corner_depths_, cells_, values_;
    FaceBuffer secondary_, primary_, primary_cells_, shell_, all_;
};

}  // namespace cutaway::pipeline
