#pragma once
// Stage 2: secondary cells clipped by the cut surface, filled, with wireframe and border lines.
#include <functional>

#include "cutaway/face_drawing.h"
#include "cutaway/frame_settings.h"
#include "cutaway/frame_targets.h"
#include "gl/program_cache.h"

namespace cutaway::pipeline {

/// What stage 2 clips against: `cut` seen from `cut_camera` and, while the view is frozen, the
/// model camera's rear shell (shaders/common/cut_lookup.glsl: a point at most `rear_margin` render
/// units in front of it is never clipped, so the frozen cut cannot open the model to the background).
struct CutClip {
    const CutTargets& cut;
    const Camera& cut_camera;
    const CameraBlocks& cameras;  ///< binds cut_camera for the passes that read the cut (common/cameras.glsl)
    const gl::Texture* view_rear_shell = nullptr;  ///< RearShellDepth::depth() from the model camera; null: none
    float rear_margin = 0;
};

class SecondaryPass {
public:
    explicit SecondaryPass(const gl::ShaderLibrary& shaders);
    /// Sets up the secondary program, then `submit` issues the face draw (a face list or the
    /// culling pass's indirect draw) into `scene`, clipped by `clip`, under the depth function the
    /// caller set, and draws the border lines. `draw` visible with settings.stage2_passes:
    /// deferred: the cut test only, into SceneTargets::deferred_framebuffer, then each visible
    /// pixel shaded once by a compute pass (ray-cast borders included); two: the cut test and
    /// depth first (SceneTargets::nearest_face), then shading once per pixel (GL_EQUAL, the first
    /// pass's face only); one, and always for all_faces: one pass with every fragment shaded, as
    /// the paper drew it.
    void draw(const FaceDrawContext& context, const std::function<void()>& submit, const FrameSettings& settings,
              const CutClip& clip, const SceneTargets& scene, DrawMode draw);
    /// The plain frame (no cut): `submit`'s faces shaded with their edges into the bound plain
    /// scene framebuffer (SceneTargets::plain_framebuffer), with early depth testing. `draw`:
    /// visible = ExposedSurface's faces with stored corners, all_faces = every face's records.
    void draw_plain(const FaceDrawContext& context, const std::function<void()>& submit, const FrameSettings& settings,
                    DrawMode draw);

private:
    /// Ray-cast borders over the visible secondary pixels of `scene` (after a shaded draw).
    void apply_raycast_borders(const FaceDrawContext& context, const SceneTargets& scene, const FrameSettings& settings,
                               const CutClip& clip);
    /// The cut's normal per cut pixel into cut_normals_ (cut_surface/cut_normals.comp) for the
    /// one-pass shading, bound at its texture unit.
    void store_cut_normals(const CutClip& clip);
    /// Stage 2's deferred shading (secondary/deferred_shading.comp) after the DEFERRED draw.
    void shade_deferred(const FaceDrawContext& context, const FrameSettings& settings, const CutClip& clip,
                        const SceneTargets& scene);

    gl::ProgramCache programs_;
    gl::ProgramCache nearest_face_;
    gl::ProgramCache plain_;
    gl::ProgramCache borders_;
    gl::ProgramCache deferred_;
    gl::Program cut_normals_program_;
    gl::Texture cut_normals_;  ///< allocated on the first one-pass frame, at the cut image's size
};

}  // namespace cutaway::pipeline
