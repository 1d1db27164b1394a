#include "cutaway/secondary_pass.h"

#include "common/shared_constants.h"
#include "gl/compute_dispatch.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

SecondaryPass::SecondaryPass(const gl::ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "common/face.vert"}, {GL_FRAGMENT_SHADER, "secondary/secondary.frag"}}),
      nearest_face_(shaders, {{GL_VERTEX_SHADER, "common/face.vert"}, {GL_FRAGMENT_SHADER, "secondary/nearest_face.frag"}}),
      plain_(shaders, {{GL_VERTEX_SHADER, "common/face.vert"}, {GL_FRAGMENT_SHADER, "secondary/plain.frag"}}),
      borders_(shaders, {{GL_COMPUTE_SHADER, "secondary/raycast_borders.comp"}}),
      deferred_(shaders, {{GL_COMPUTE_SHADER, "secondary/deferred_shading.comp"}}),
      cut_normals_program_(shaders.build({{GL_COMPUTE_SHADER, "cut_surface/cut_normals.comp"}})) {}

namespace {
/// The cut camera's block and the uniforms of shaders/common/cut_lookup.glsl; `camera`: the model camera.
void set_cut_lookup(const gl::Program& p, const CutClip& clip, const Camera& camera) {
    clip.cameras.bind_cut(clip.cut_camera);
    gl::set_uniform(p, "cut_surface", 1);
    clip.cut.surface.bind(1);
    gl::set_uniform(p, "cut_rear_clamp", 5);
    clip.cut.rear_clamp.bind(5);
    if (!clip.view_rear_shell) return;  // the programs are built without VIEW_REAR_SHELL then
    gl::set_uniform(p, "view_rear_shell", 6);
    clip.view_rear_shell->bind(6);
    gl::set_uniform(p, "view_rear_view", camera.view);
    gl::set_uniform(p, "view_rear_range", glm::vec2(camera.near_plane, camera.far_plane));
    gl::set_uniform(p, "view_rear_margin", clip.rear_margin);
}
const glm::vec3 shell_cut_colour(0.85f, 0.1f, 0.1f);
/// Texture unit of the stored cut normals (the face programs' grid takes 8-13, the cut 1 and 5-7).
constexpr unsigned cut_normals_texture_unit = 15;
/// The variants every stage-2 program takes from where the cut was made: VIEW_REAR_SHELL
/// (common/cut_lookup.glsl) while the view is frozen, CUT_CAMERA_IS_VIEW (the cut made from the
/// model `camera` itself) otherwise.
gl::ShaderDefines cut_view_defines(const Camera& camera, const CutClip& clip) {
    gl::ShaderDefines defines;
    if (clip.view_rear_shell) defines.emplace_back("VIEW_REAR_SHELL", "");
    if (same_view(camera, clip.cut_camera)) defines.emplace_back("CUT_CAMERA_IS_VIEW", "");
    return defines;
}

/// The uniforms of shaders/common/secondary_shading.glsl's ray-cast border test (its camera: the
/// bound view block, common/cameras.glsl).
void set_border_uniforms(const gl::Program& p, const FrameSettings& settings) {
    gl::set_uniform(p, "border_width", settings.border_width_px);
    gl::set_uniform(p, "shell_cut_colour", shell_cut_colour);
}

/// The compute passes read the cut surface and its rear-clamp mask as images (common/cut_lookup.glsl
/// CUT_IMAGES) at shared::img_cut_surface and img_cut_rear_clamp.
void bind_cut_images(const CutClip& clip) {
    glBindImageTexture(shared::img_cut_surface, clip.cut.surface.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(shared::img_cut_rear_clamp, clip.cut.rear_clamp.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8);
}

/// The shading variants of common/secondary_shading.glsl that `settings` asks for.
void add_shading_defines(gl::ShaderDefines& defines, const FrameSettings& settings) {
    defines.emplace_back(settings.border == BorderMode::raycast ? "BORDER_RAYCAST" : "BORDER_THRESHOLD", "");
    if (settings.hide_internal_lines) defines.emplace_back("HIDE_INTERNAL_LINES", "");
}

/// One invocation of `program` per pixel of `camera`'s image.
void dispatch_per_pixel(const gl::Program& program, const Camera& camera) {
    gl::dispatch_over(program, camera.width, camera.height);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
}
}  // namespace

void SecondaryPass::apply_raycast_borders(const FaceDrawContext& context, const SceneTargets& scene,
                                          const FrameSettings& settings, const CutClip& clip) {
    const Camera& camera = context.camera;
    gl::ShaderDefines defines = cut_view_defines(camera, clip);
    defines.emplace_back("CUT_IMAGES", "");
    bind_cut_images(clip);
    const gl::Program& p = borders_.get(defines);
    clip.cameras.bind_view(camera);
    set_cut_lookup(p, clip, camera);
    set_border_uniforms(p, settings);
    gl::set_uniform(p, "hide_internal_lines", settings.hide_internal_lines);
    context.grid.set_geometry_uniforms(p);  // the cut fill's line fade reads the cells' corners
    context.grid.bind_geometry();
    glBindImageTexture(shared::img_scene_colour, scene.colour.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
    glBindImageTexture(shared::img_scene_id, scene.id.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RG32UI);
    glBindImageTexture(shared::img_scene_face_plane, scene.face_plane.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32UI);  // image loads: cheaper than texelFetch on llvmpipe
    glBindImageTexture(shared::img_scene_normal_depth, scene.normal_depth.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32UI);
    gl::wait_for_draws_before_image_loads();
    p.use();
    dispatch_per_pixel(p, camera);
}

void SecondaryPass::store_cut_normals(const CutClip& clip) {
    const Camera& cut_camera = clip.cut_camera;
    if (cut_normals_.width() != cut_camera.width || cut_normals_.height() != cut_camera.height) {
        cut_normals_ = {};  // the old image goes before the new one is allocated
        cut_normals_ = gl::Texture(GL_TEXTURE_2D, GL_RGBA32F, cut_camera.width, cut_camera.height);
    }
    bind_cut_images(clip);  // cut_normals.comp defines CUT_IMAGES itself
    glBindImageTexture(shared::img_cut_normals, cut_normals_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    clip.cameras.bind_cut(cut_camera);
    cut_normals_program_.use();
    gl::dispatch_over(cut_normals_program_, cut_camera.width, cut_camera.height);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    cut_normals_.bind(cut_normals_texture_unit);
}

void SecondaryPass::shade_deferred(const FaceDrawContext& context, const FrameSettings& settings, const CutClip& clip,
                                   const SceneTargets& scene) {
    const Camera& camera = context.camera;
    gl::ShaderDefines defines = cut_view_defines(camera, clip);
    add_shading_defines(defines, settings);
    defines.emplace_back("CUT_IMAGES", "");
    bind_cut_images(clip);
    const gl::Program& p = deferred_.get(defines);
    prepare_face_program(p, context);
    set_cut_lookup(p, clip, camera);
    set_border_uniforms(p, settings);
    glBindImageTexture(shared::img_scene_colour, scene.colour.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glBindImageTexture(shared::img_scene_id, scene.id.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RG32UI);
    glBindImageTexture(shared::img_scene_face_plane, scene.face_plane.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32UI);
    glBindImageTexture(shared::img_scene_normal_depth, scene.normal_depth.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32UI);
    gl::wait_for_draws_before_image_loads();
    dispatch_per_pixel(p, camera);
}

void SecondaryPass::draw(const FaceDrawContext& context, const std::function<void()>& submit, const FrameSettings& settings,
                         const CutClip& clip, const SceneTargets& scene, DrawMode draw) {
    gl::ShaderDefines defines = cut_view_defines(context.camera, clip);
    defines.emplace_back("CULL_FRONT_INTERIOR", "");
    if (draw == DrawMode::visible && settings.stage2_passes == Stage2Passes::deferred) {
        // The cut test only: the borders and hidden lines are shade_deferred's.
        defines.emplace_back("DEFERRED", "");
        const gl::Program& p = programs_.get(defines);
        prepare_face_program(p, context);
        set_cut_lookup(p, clip, context.camera);
        gl::set_uniform(p, "line_width", settings.line_width_px);
        scene.deferred_framebuffer.bind();
        submit();
        shade_deferred(context, settings, clip, scene);
        return;
    }
    const gl::ShaderDefines nearest_defines = defines;
    add_shading_defines(defines, settings);
    store_cut_normals(clip);
    defines.emplace_back("STORED_CUT_NORMALS", "");
    const bool two_passes = draw == DrawMode::visible && settings.stage2_passes == Stage2Passes::two;
    GLint depth_function = GL_LESS;
    if (two_passes) {
        const gl::Program& nearest = nearest_face_.get(nearest_defines);
        prepare_face_program(nearest, context);
        set_cut_lookup(nearest, clip, context.camera);
        const NearestFaceTarget& nearest_face = scene.nearest_face();
        nearest_face.clear();
        nearest_face.framebuffer.bind();
        submit();
        glGetIntegerv(GL_DEPTH_FUNC, &depth_function);
        glDepthFunc(GL_EQUAL);
        glDepthMask(GL_FALSE);
        defines.emplace_back("NEAREST_FACE_TESTED", "");
        nearest_face.index.bind(shared::tex_nearest_face);
    }
    scene.framebuffer.bind();
    const gl::Program& p = programs_.get(defines);
    prepare_face_program(p, context);
    set_cut_lookup(p, clip, context.camera);
    gl::set_uniform(p, "line_width", settings.line_width_px);
    gl::set_uniform(p, "border_width", settings.border_width_px);
    gl::set_uniform(p, "shell_cut_colour", shell_cut_colour);
    gl::set_uniform(p, "cut_normals", int(cut_normals_texture_unit));
    submit();
    if (two_passes) {
        glDepthMask(GL_TRUE);
        glDepthFunc(GLenum(depth_function));
    }
    if (settings.border == BorderMode::raycast) apply_raycast_borders(context, scene, settings, clip);
}

void SecondaryPass::draw_plain(const FaceDrawContext& context, const std::function<void()>& submit,
                               const FrameSettings& settings, DrawMode draw) {
    const gl::ShaderDefines defines = draw == DrawMode::visible
        ? gl::ShaderDefines{{"PLAIN_FRAME", ""}, {"STORED_CORNERS", ""}, {"CULL_HIDDEN_BACK", ""}}
        : gl::ShaderDefines{{"PLAIN_FRAME", ""}, {"CULL_FRONT_INTERIOR", ""}};
    const gl::Program& p = plain_.get(defines);
    prepare_face_program(p, context);
    gl::set_uniform(p, "line_width", settings.line_width_px);
    submit();
}

}  // namespace cutaway::pipeline
