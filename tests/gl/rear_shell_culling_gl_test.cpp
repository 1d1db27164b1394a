// The rear shell (cutaway/rear_shell_depth.h) lets the rasteriser cull the triangles facing the
// eye, per winding part of the outer faces (GridBuffers::WoundFaces, common/face_corner.vert), and
// leaves out the walls of enclosed pockets of inactive cells (grid/enclosed_pockets.h). A ray
// leaves the closed outer surface (shell and uncovered fault faces) through a back-facing
// triangle, and never at a pocket's wall, so the farthest depth must barely change when nothing
// is culled and the walls are drawn too: this compares the pass against the same program drawing
// every shell and uncovered fault face without culling, at every pixel, from random cameras, on
// models whose cells turn either way and on a generated model with enclosed pockets. A wrong
// glFrontFace for a part would keep its front faces, which lie nearer: every pixel of that part
// would differ.
// What may differ, and why the bounds are what they are:
// - the culled draw keeps a subset of the fragments, so it is never farther (exact);
// - coincident or nearly coincident faces facing opposite ways (the top and bottom of a pinched-out
//   or razor-thin cell, a face and the one across a fault) tie within rounding, and the unculled
//   draw may keep the front-facing one: up to 3e-5 of the depth range seen on petra, 1e-7 on the
//   faulted model; such pixels are a few in 10,000 of the covered ones (at most 16 of 26,428);
// - a pixel on the model's outline can be covered by a front-facing triangle's edge only, its
//   back-facing neighbour not reaching the pixel centre (1 pixel on banal6 in 64 views).
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "app_core/model_source.h"
#include "cutaway/face_drawing.h"
#include "cutaway/rear_shell_depth.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

constexpr int width = 320, height = 240;

std::vector<float> read_depth(const gl::Texture& depth) {
    std::vector<float> texels(std::size_t(width) * height);
    glGetTextureImage(depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
    return texels;
}

/// Farthest depth of every triangle of the shell and uncovered fault faces, pocket walls included,
/// none culled, in the rear shell's depth encoding.
std::vector<float> unculled_rear_depth(const gl::Program& program, const pipeline::GridBuffers& buffers,
                                       const pipeline::FaceBuffer& faces, const pipeline::Camera& camera,
                                       const pipeline::CameraBlocks& cameras) {
    gl::Texture depth(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height);
    gl::Framebuffer framebuffer;
    framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
    const std::array<GLenum, 1> none{GL_NONE};
    framebuffer.finish(none, "unculled rear shell");
    const float zero = 0.0f;
    glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &zero);
    framebuffer.bind();
    pipeline::prepare_face_program(program, pipeline::FaceDrawContext{buffers, camera, cameras});
    pipeline::set_depth_encoding(program, camera);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    buffers.draw_faces(faces);
    glDepthFunc(GL_LESS);
    return read_depth(depth);
}

struct WindingParts {
    std::size_t counter_clockwise = 0, clockwise = 0;
    std::size_t pocket_walls = 0;  ///< faces the pass leaves out as walls of enclosed pockets
};

WindingParts check_model(const grid::CornerPointGrid& grid, unsigned seed, const std::string& name) {
    const pipeline::ModelFrame frame = pipeline::make_model_frame(grid, 0.0);
    const pipeline::GridLayout layout =
        pipeline::build_grid_layout(grid, grid::FaceClassification(grid, grid::default_face_tolerance(grid)), frame);
    const pipeline::GridBuffers buffers(layout, grid.zcorn(), frame);
    const pipeline::FaceBuffer with_walls = pipeline::FaceBuffer::from(pipeline::outer_faces(
        layout, grid.zcorn(), pipeline::active_cells(layout, grid.dims()), std::vector<bool>(grid.cell_count(), false)));
    const pipeline::CameraBlocks cameras;
    pipeline::RearShellDepth rear(GlEnvironment::shaders(), cameras, width, height);
    const gl::Program unculled = GlEnvironment::shaders().build(
        {{GL_VERTEX_SHADER, "common/face_corner.vert"}, {GL_FRAGMENT_SHADER, "cut_surface/seed_geometry.frag"}});
    std::mt19937 random(seed);
    for (int view = 0; view < 8; ++view) {
        const pipeline::Camera camera = pipeline::make_orbit_camera(frame, random_pose(random), width, height);
        rear.render(buffers, camera, true);  // no primaries in these buffers
        const std::vector<float> culled = read_depth(rear.depth());
        const std::vector<float> reference = unculled_rear_depth(unculled, buffers, with_walls, camera, cameras);
        std::size_t covered = 0, farther = 0, differing = 0, far_apart = 0;
        for (std::size_t p = 0; p < culled.size(); ++p) {
            covered += reference[p] > 0.0f;
            farther += culled[p] > reference[p];
            differing += culled[p] != reference[p];
            far_apart += reference[p] - culled[p] > 1e-4f;
        }
        const std::string where = name + " view " + std::to_string(view) + ": " + std::to_string(covered) + " pixels covered";
        EXPECT_GT(covered, 0u) << where;
        EXPECT_EQ(farther, 0u) << where;
        EXPECT_LE(differing, covered / 1000) << where;
        EXPECT_LE(far_apart, 1u) << where;
    }
    return {buffers.outer_faces().counter_clockwise.count, buffers.outer_faces().clockwise.count,
            with_walls.count - buffers.outer_faces().count()};
}

TEST(RearShellCulling, FarthestDepthAsWithoutCullingOnGeneratedModels) {
    WindingParts parts = check_model(petra(), 3, "petra");
    const WindingParts faulted = check_model(faulted_model_with_inactive_cells({24, 20, 8}, 0.15, 11), 5, "faulted");
    parts.counter_clockwise += faulted.counter_clockwise;
    parts.clockwise += faulted.clockwise;
    EXPECT_GT(parts.counter_clockwise + parts.clockwise, 0u);
    EXPECT_GT(faulted.pocket_walls, 0u);  // the generated model has enclosed pockets to leave out
}

TEST(RearShellCulling, FarthestDepthAsWithoutCullingOnRealGridsOfBothHandednesses) {
    const std::string small = std::string(CUTAWAY_SHARED_DATA) + "/grdecl/small/";
    WindingParts parts = check_model(reek(), 7, "reek");
    for (const char* file : {"sixcells_lefthanded_hdr1.grdecl", "sixcells2_rhand_hdr1.grdecl", "banal6.grdecl"}) {
        const app::LoadedModel model = app::load_model({small + file}, std::size_t(1) << 30);
        const WindingParts p = check_model(model.grid, 13, file);
        parts.counter_clockwise += p.counter_clockwise;
        parts.clockwise += p.clockwise;
    }
    // Both winding parts were drawn and checked.
    EXPECT_GT(parts.counter_clockwise, 0u);
    EXPECT_GT(parts.clockwise, 0u);
}

}  // namespace
}  // namespace cutaway::test
