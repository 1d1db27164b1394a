#include "volume/gpu_ray_caster.h"

#include <glm/gtc/type_ptr.hpp>

#include "volume/annotations.h"
#include "volume/view_geometry.h"

namespace cutaway::volume {

namespace {
constexpr GLuint kExitPointsUnit = 0, kVolumeUnit = 1, kTableUnit = 2, kBlocksUnit = 3;

/// Variant bit of each optional part, and its shader define.
struct Variant {
    unsigned bit;
    const char* define;
    bool RayCastSettings::*enabled;
};
constexpr std::array<Variant, 4> kVariants{{{1u, "OPACITY_CORRECTION", &RayCastSettings::opacity_correction},
                                            {2u, "JITTER", &RayCastSettings::jitter},
                                            {4u, "EARLY_TERMINATION", &RayCastSettings::early_termination},
                                            {8u, "EMPTY_SPACE_SKIPPING", &RayCastSettings::empty_space_skipping}}};
}  // namespace

GpuRayCaster::GpuRayCaster(const gl::ShaderLibrary& shaders, const VolumeScene& scene)
    : shaders_(shaders),
      scene_(&scene),
      volume_levels_(GL_R8, scene.volume->dims.samples, scene.volume->dims.crosslines, scene.volume->dims.inlines),
      transfer_table_(GL_TEXTURE_1D, GL_RGBA32F, 256) {
    volume_levels_.upload(GL_RED, GL_UNSIGNED_BYTE, scene.volume->levels.data());
    volume_levels_.set_filter(GL_LINEAR);
    exit_program_ = shaders_.build({{GL_VERTEX_SHADER, "volume/box.vert"}, {GL_FRAGMENT_SHADER, "volume/exit_points.frag"}});
    set_transfer(scene);
}

void GpuRayCaster::set_transfer(const VolumeScene& scene) {
    scene_ = &scene;
    glTextureSubImage1D(transfer_table_.id(), 0, 0, 256, GL_RGBA, GL_FLOAT, scene.table.data());
    const CubeDims& b = scene.blocks.blocks;
    occupied_blocks_ = Texture3D(GL_R8UI, b.samples, b.crosslines, b.inlines);
    occupied_blocks_.upload(GL_RED_INTEGER, GL_UNSIGNED_BYTE, scene.occupied.data());
}

const gl::Program& GpuRayCaster::ray_program(const RayCastSettings& settings) {
    unsigned key = 0;
    gl::ShaderDefines defines;
    for (const Variant& v : kVariants)
        if (settings.*v.enabled) {
            key |= v.bit;
            defines.emplace_back(v.define, "1");
        }
    gl::Program& program = ray_programs_[key];
    if (!program)
        program = shaders_.build({{GL_VERTEX_SHADER, "volume/box.vert"}, {GL_FRAGMENT_SHADER, "volume/ray_cast.frag"}},
                                 defines);
    return program;
}

void GpuRayCaster::ensure_targets(int width, int height) {
    if (targets_.width == width && targets_.height == height) return;
    Targets t;
    t.width = width;
    t.height = height;
    t.exit_points = gl::Texture(GL_TEXTURE_2D, GL_RGBA32F, width, height);
    t.colour = gl::Texture(GL_TEXTURE_2D, GL_RGBA8, width, height);
    t.counts = gl::Texture(GL_TEXTURE_2D, GL_RG32UI, width, height);
    t.exit_framebuffer.attach(GL_COLOR_ATTACHMENT0, t.exit_points);
    const GLenum exit_buffers[] = {GL_COLOR_ATTACHMENT0};
    t.exit_framebuffer.finish(exit_buffers, "volume exit points");
    t.ray_framebuffer.attach(GL_COLOR_ATTACHMENT0, t.colour);
    t.ray_framebuffer.attach(GL_COLOR_ATTACHMENT1, t.counts);
    const GLenum ray_buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    t.ray_framebuffer.finish(ray_buffers, "volume ray cast");
    targets_ = std::move(t);
}

CastResult GpuRayCaster::render(const RayCastSettings& settings, gl::StageTimer& timer) {
    validate(settings);
    const ViewGeometry view = make_view(scene_->volume->dims, settings);
    ensure_targets(settings.width, settings.height);
    const gl::Program& ray = ray_program(settings);

    glViewport(0, 0, settings.width, settings.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glEnable(GL_CULL_FACE);
    glFrontFace(view.mirrored ? GL_CW : GL_CCW);
    empty_vertex_array_.bind();
    auto set_box_uniforms = [&](const gl::Program& program) {
        glProgramUniformMatrix4fv(program.id(), program.uniform("voxel_to_clip"), 1, GL_FALSE,
                                  glm::value_ptr(view.voxel_to_clip));
        glProgramUniform3fv(program.id(), program.uniform("box"), 1, glm::value_ptr(view.box));
    };

    gl::timed_stage(timer, "exit_points", [&] {
        const GLfloat none[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(targets_.exit_framebuffer.id(), GL_COLOR, 0, none);
        targets_.exit_framebuffer.bind();
        glCullFace(GL_FRONT);
        exit_program_.use();
        set_box_uniforms(exit_program_);
        glDrawArrays(GL_TRIANGLES, 0, 36);
    });

    gl::timed_stage(timer, "ray_cast", [&] {
        const Rgba& bg = settings.background;
        const GLfloat background[4] = {bg.r, bg.g, bg.b, 1};
        const GLuint zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(targets_.ray_framebuffer.id(), GL_COLOR, 0, background);
        glClearNamedFramebufferuiv(targets_.ray_framebuffer.id(), GL_COLOR, 1, zero);
        targets_.ray_framebuffer.bind();
        glCullFace(GL_BACK);
        ray.use();
        set_box_uniforms(ray);
        glProgramUniform1f(ray.id(), ray.uniform("step_length"), settings.step);
        glProgramUniform1f(ray.id(), ray.uniform("early_termination_alpha"), settings.early_termination_alpha);
        glProgramUniform4fv(ray.id(), ray.uniform("background"), 1, background);
        glProgramUniform1f(ray.id(), ray.uniform("block_size"), float(scene_->blocks.block_size));
        targets_.exit_points.bind(kExitPointsUnit);
        volume_levels_.bind(kVolumeUnit);
        transfer_table_.bind(kTableUnit);
        occupied_blocks_.bind(kBlocksUnit);
        glDrawArrays(GL_TRIANGLES, 0, 36);
    });

    CastResult result;
    gl::timed_stage(timer, "readback", [&] {
        result.image = gl::read_rgba(targets_.ray_framebuffer.id(), GL_COLOR_ATTACHMENT0, settings.width, settings.height);
        std::vector<GLuint> counts(std::size_t(settings.width) * std::size_t(settings.height) * 2);
        glGetTextureImage(targets_.counts.id(), 0, GL_RG_INTEGER, GL_UNSIGNED_INT, GLsizei(counts.size() * sizeof(GLuint)),
                          counts.data());
        for (std::size_t k = 0; k < counts.size(); k += 2) {
            result.samples += counts[k];
            result.rays += counts[k + 1];
        }
    });
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (settings.colour_bar) draw_annotations(result.image, *scene_, view, settings);
    return result;
}

}  // namespace cutaway::volume
