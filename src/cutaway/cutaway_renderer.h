#pragma once
// One cutaway frame, stage by stage (SPEC.md section 2): cut surface, mean filter, secondaries,
// primaries and feature lines, SSAO, composite. Every stage is fenced and timed.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/shared_constants.h"
#include "cutaway/active_cell_rank.h"
#include "cutaway/camera.h"
#include "cutaway/camera_blocks.h"
#include "cutaway/colour_bar.h"
#include "cone_field/cone_image.h"
#include "cutaway/cut_surface/cone_field_strategy.h"
#include "cutaway/cut_surface/cut_resolve.h"
#include "cutaway/cut_surface/cut_surface_strategy.h"
#include "cutaway/cut_surface/opening_cut.h"
#include "cutaway/cut_surface/volume_cut.h"
#include "cutaway/exposed_surface.h"
#include "cutaway/frame_plan.h"
#include "cutaway/frame_settings.h"
#include "cutaway/frame_targets.h"
#include "cutaway/grid_buffers.h"
#include "cutaway/post/composite.h"
#include "cutaway/post/mean_filter.h"
#include "cutaway/post/ssao.h"
#include "cutaway/primary_pass.h"
#include "cutaway/rear_shell_depth.h"
#include "cutaway/selection/gpu_primary_selection.h"
#include "cutaway/selection/primary_centroid.h"
#include "cutaway/temporal/cell_openings.h"
#include "cutaway/secondary_pass.h"
#include "cutaway/visibility/visible_faces.h"
#include "cutaway/well_labels.h"
#include "cutaway/frame_caption.h"
#include "cutaway/well_tubes.h"
#include "gl/image.h"
#include "gl/stage_timer.h"
#include "grid/corner_point_grid.h"

namespace cutaway::pipeline {

/// Stage names in stats.json (stages_ms).
/// `culling`: the visible path's pyramid + selection pass (absent with --draw all-faces).
inline constexpr const char* stage_names[] = {"cut_surface", "mean_filter", "culling", "secondary", "primary", "ssao", "post"};

struct FrameTimes {
    std::vector<gl::StageTime> stages;  ///< in execution order
    gl::StageTime total;                ///< fenced wall time of the whole frame
};

/// Per-pixel ids read back: compact cell + 1 (0 = background) and flags (frame_outputs.glsl).
struct IdImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> cell;
    std::vector<std::uint32_t> flags;
};

/// A float image (rows bottom to top, as GL stores them).
struct FloatImage {
    int width = 0;
    int height = 0;
    std::vector<float> values;
};

/// Faces each pass of the last frame submitted (stats.json faces_drawn); `culling` is set for the
/// visible path (read back from the GPU on request).
struct FacesDrawn {
    std::uint64_t secondary = 0;
    std::uint64_t primary = 0;
    std::uint64_t shell_contours = 0;
    std::optional<CullingCounts> culling;
};

/// Hooks through which a caller runs one frame across several renderers, each drawing one block of
/// the model (src/distributed/). The renderer calls them at fixed points and never knows who
/// combines what; with no hooks set the frame is the single-process one.
struct FrameHooks {
    /// Replaces each DEPTH32F image by its per-pixel max over all renderers. Called after stage 1
    /// (timed as stage "cut_combine", with the resolve pass that follows) on the strategy's cut
    /// and the rear shell (unless see-through), before the cut is resolved and filtered; for the
    /// cone-field strategies on their seed image instead of the cut (inside stage 1, before the
    /// transform), so every renderer transforms the same seeds; while the view is frozen, also on
    /// the model camera's rear shell at the start of stage 2.
    std::function<void(const std::vector<const gl::Texture*>& depth_images)> combine_max;
    /// Sums the primaries' centres over all renderers (the cone-field strategies' slope is taken
    /// at the centroid of all primaries). Called whenever the selection changes.
    std::function<CentreSum(const CentreSum& own)> sum_centres;
    /// After stage 3, before SSAO and post: combines the G-buffer over all renderers. Timed as
    /// stage "composite".
    std::function<void(const SceneTargets& scene)> combine_scene;
    /// Whether this renderer runs the screen-space passes on the combined G-buffer (false: its
    /// final image is left unwritten; only one renderer of a distributed frame runs them).
    bool screen_passes = true;
};

using shared::flag_border, shared::flag_cut_fill, shared::flag_edge, shared::flag_primary, shared::flag_shell_cut;

/// What select() takes: primary flags (one per Eclipse cell), or a range of the colouring values
/// (and an IJK box) for the GPU selection.
struct Primaries {
    Primaries(std::vector<std::uint8_t> cell_flags) : flags(std::move(cell_flags)) {}
    Primaries(const grid::PrimaryRange& value_range, const std::optional<grid::IjkBox>& ijk_box = std::nullopt)
        : range(value_range), box(ijk_box) {}
    /// No primary cell (`--primaries none`: the cut volumes alone cut).
    static Primaries none() { return Primaries(std::vector<std::uint8_t>{}); }
    std::optional<std::vector<std::uint8_t>> flags;  ///< one per Eclipse cell; empty: none()
    grid::PrimaryRange range;
    std::optional<grid::IjkBox> box;
};

/// Whether render() fences each stage (stage times) or only the whole frame.
enum class Fencing { each_stage, frame_only };

/// How set_colouring sends the values: float32 (4 bytes per active cell, exact: primaries can be
/// selected by range over them) or unorm16 (2 bytes, quantised over the values' span, for
/// colouring only: the primaries come as flags; quantised_values.h).
enum class ValueStorage { float32, unorm16 };

/// The renderer's state as a run reports it (status()).
struct RendererStatus {
    int width = 0;
    int height = 0;
    std::size_t primary_cells = 0;
    /// The registry strategy a frame with the settings draws its cut with: settings.strategy, or
    /// for "auto" the one it picks for the primaries of every renderer (cut_strategy_choice.h).
    std::string cut_strategy;
    std::uint64_t auto_sweep_from = 0;  ///< primary cells from which "auto" picks frustum-sweep on this device
    /// Columns at the image's right edge a framed camera leaves to the colour bar (0 without one):
    /// the `reserved_right_px` of make_orbit_camera.
    float colour_bar_reserved_width = 0;
    /// Rows at the image's top a framed camera leaves to settings.caption (0 without one): the
    /// `reserved_top_px` of make_orbit_camera (frame_caption.h caption_reserved_rows).
    float caption_reserved_height = 0;
    bool frozen = false;
    std::size_t frames_redrawn = 0;      ///< frames drawn twice because the culling's face buffer grew
    /// Bytes of the culling's face count read back after frames (0 while its buffer holds every
    /// selectable face: models up to about 5M cells).
    std::size_t face_count_readback_bytes = 0;
    std::size_t cut_readback_bytes = 0;  ///< what the last frame's strategy read back (stats.json readback_bytes)
    /// Bytes of GPU selections read back so far: only for a strategy that builds from the flags
    /// (CutSurfaceEntry::selection_on_cpu) or the full secondary list (DrawMode::all), once per selection.
    std::size_t selection_readback_bytes = 0;
    /// Bytes of GL buffers and textures by part: the grid (geometry, values, face lists), the visible
    /// path's culling, the primary selection, the plain frame's exposed surface (0 until drawn).
    std::vector<std::pair<std::string, std::size_t>> gpu_memory_by_part;
    std::size_t gpu_memory_bytes() const;
    FramePlan last_plan;                    ///< the passes of the last frame (FramePlan::describe in stats.json)
    std::size_t cut_volume_triangles = 0;   ///< triangles of the cut volumes set
    std::vector<WellHead> well_heads;       ///< the wells drawn: name, colour, render-space position
    /// Bytes sent to the GPU since construction by set_colouring, select (flags) and
    /// set_opening_cells: what switching a time step costs.
    std::size_t uploaded_bytes = 0;
    glm::vec3 primary_centroid{0};  ///< render space, of this renderer's primaries (0 without any)
};

class CutawayRenderer {
public:
    /// Called by the constructor once it has read the grid's corner depths for the last time (the
    /// geometry buffers and the culling's bricks are built; the culling and selection buffers, the
    /// render targets and the first colouring are not yet allocated), e.g. to release them: then
    /// they never share memory with what the rest of the set-up allocates.
    using CornerDepthsRead = std::function<void()>;

    /// Uploads the grid. Throws std::invalid_argument for an empty model or a size above the GL
    /// limit, gl::GlError for GL failures. After construction only the grid's dimensions and
    /// ACTNUM are read again: its corner depths may be released (CornerPointGrid::release_corner_depths),
    /// at the earliest from `corner_depths_read`.
    CutawayRenderer(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& grid, double z_scale, int width,
                    int height, const CornerDepthsRead& corner_depths_read = {});
    /// One block of a larger model (src/distributed/): `frame` is the whole model's (every block
    /// draws in the same render space and camera), `classes` the block's faces classified with the
    /// cells around the block, so its cut boundary is not drawn as shell.
    CutawayRenderer(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& grid, const ModelFrame& frame,
                    const grid::FaceClassification& classes, int width, int height,
                    const CornerDepthsRead& corner_depths_read = {});

    /// Hooks combine every rank's frame, so no rank may draw a frame again alone: the culling's
    /// face buffer is sized for every face at once (see render).
    void set_hooks(FrameHooks hooks);

    const ModelFrame& frame() const { return frame_; }
    /// Renders frames of `width` x `height` from now on: the per-pixel targets are reallocated,
    /// the model's buffers and programs stay (the viewer's render size while the view moves).
    /// Freeze view ends: the caller freezes again with a camera of the new size.
    void resize(int width, int height);

    /// Colours cells by `values` (one per Eclipse cell) mapped from the label's range.
    void set_colouring(const std::vector<float>& values, const ColourBarLabel& label,
                       ValueStorage storage = ValueStorage::float32);
    /// The primary range the colour bar marks (none: no mark), uploading nothing: the viewer's range
    /// follows the user's slider; the colouring stays as set_colouring left it.
    void mark_primary_range(const std::optional<ColourBarLabel::Span>& range) { label_.primary_range = range; }
    /// The primary cells: given as flags (one per Eclipse cell), or chosen on the GPU as the active
    /// cells whose colouring value lies in a range (and inside an IJK box), which uploads nothing.
    /// A range needs the values at float32: throws std::logic_error after unorm16 values.
    void select(const Primaries& primaries);

    /// The user's cut volumes (closed meshes in model coordinates), uploaded once; every frame's
    /// stage 1 draws them into the cut beside the primaries' (FramePass::volume_cut). An empty list
    /// removes them. A frozen cut is made again.
    void set_cut_volumes(const std::vector<shapes::TriangleMesh>& meshes);

    /// The point whose depth the seed strategies match their cone slope to the frustum walls at
    /// (cone_field_strategy.h): the primaries' centroid unless set here. A smooth animation eases
    /// it towards the centroid (every change of the selection moves the centroid, and with the
    /// slope every wall of the cut). std::nullopt: the centroid again.
    void set_cone_reference(const std::optional<glm::vec3>& point);

    /// Cells whose cut opens or closes over an animation's frames (temporal::CellOpenings, smooth
    /// coherence): each frame's stage 1 draws their partial frustums into the cut beside the
    /// primaries' (FramePass::opening_cut); 8 bytes per cell uploaded. An empty list removes them.
    /// Throws std::invalid_argument for an inactive or out-of-range cell.
    void set_opening_cells(const std::vector<temporal::OpeningCell>& cells);

    /// The wells drawn from now on (an empty set: none): their tubes are built and uploaded here,
    /// once per set; frame() holds their wellheads, so that a framed camera shows them. Throws
    /// std::invalid_argument for a well whose path or radius makes no tube.
    void set_wells(const WellSet& wells);

    /// Freeze view: the cut of `camera` is kept (stage 1 is not re-run) until freeze(std::nullopt).
    void freeze(const std::optional<Camera>& camera);

    /// Renders one frame with the strategy named in settings. The culling's face buffer holds
    /// what frames have needed so far: a frame that selected more faces than it holds grows it
    /// and is drawn again (counted in status().frames_redrawn; the times are the second drawing's).
    /// Fencing::frame_only: the stages are not fenced (only `total` is timed, one glFinish at its
    /// end), as a user's frame runs with its stages overlapping.
    FrameTimes render(const FrameSettings& settings, const Camera& camera, Fencing fencing = Fencing::each_stage);
    /// The plain shaded frame of the whole model (no cut, no post), timed: the exposed faces
    /// (`visible`) or every face of every active cell (`all_faces`).
    gl::StageTime render_baseline(const Camera& camera, DrawMode draw = DrawMode::visible);

    /// The renderer's state for a frame with `settings` (no GPU read-back).
    RendererStatus status(const FrameSettings& settings = {}) const;

private:
    friend class FrameReadback;  // renderer_readback.h: the last frame's images for metrics and tests
    friend class RendererProbe;

    /// The first constructor's work once the active cells' bounds are known (computed once: the
    /// frame and the face tolerance both need them).
    CutawayRenderer(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& grid, const grid::Box3& bounds,
                    double z_scale, int width, int height, const CornerDepthsRead& corner_depths_read);
    /// Builds the cell layout with `lay_out` first: a face classification made there is freed
    /// before the geometry buffers are (scale-10m: 6 bytes per cell less at the set-up's peak).
    using LayOut = std::function<GridLayout(const ModelFrame&)>;
    CutawayRenderer(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& grid, const ModelFrame& frame,
                    const LayOut& lay_out, int width, int height, const CornerDepthsRead& corner_depths_read);

    /// What one pass of the plan needs: the frame's settings, cameras and plan.
    struct FrameStep {
        const FrameSettings& settings;
        const Camera& camera;
        const Camera& cut_camera;
        const FramePlan& plan;
    };
    FrameTimes render_once(const FrameSettings& settings, const Camera& camera);
    /// The registry strategy a frame with `settings` draws its cut with (RendererStatus::cut_strategy).
    std::string cut_strategy(const FrameSettings& settings) const;
    /// What stage 1 hands the strategy for `settings` and the cut camera.
    CutSurfaceInputs cut_inputs(const FrameSettings& settings, const Camera& cut_camera) const;
    void set_primaries(const std::vector<std::uint8_t>& flags);
    void select_range(const grid::PrimaryRange& range, const std::optional<grid::IjkBox>& box);
    /// Per-pixel cell + 1 and flags of the last frame (frame_outputs.glsl).
    IdImage read_ids() const;
    gl::RgbaImage read_image() const;
    std::vector<std::uint32_t> read_eclipse_ids() const;
    float colour_bar_reserved_width(const FrameSettings& settings) const;
    RendererState state_for(const CutSurfaceEntry& strategy) const;
    void run_pass(FramePass pass, const FrameStep& step);
    void draw_strategy_cut(const FrameStep& step);
    void draw_secondaries(const FrameStep& step);
    FaceDrawContext draw_context(const Camera& camera) const;
    const Camera& cut_camera_for(const Camera& camera) const { return frozen_camera_ ? *frozen_camera_ : camera; }
    CutSurfaceStrategy& strategy(const std::string& name);
    /// Render units the rear-shell clamp keeps in front of the rear shell seen from `camera`.
    float rear_margin(const Camera& camera) const;
    /// Normals and rear-shell clamp of the cut, clamped in front of the rear shell (unless
    /// see_through), into cut_: from `filtered` (the mean filter's output) or, if null, cut_.depth.
    void resolve_cut(const gl::FloatImageBuffer* filtered, const FrameSettings& settings, const Camera& cut_camera);
    /// Freeze view: the rear shell seen from the model `camera`, which stage 2 keeps (CutClip).
    /// Reuses rear_shell_ (only needed while the cut is made).
    const gl::Texture& render_view_rear_shell(const Camera& camera, bool primaries_drawn);
    /// Stage 2's faces for `draw`: the culling pass's selection, or the full secondary list.
    void draw_secondary_faces(DrawMode draw);
    const FaceBuffer& secondary_face_list();
    void selection_changed();
    /// Reads the selection back to primary_flags_ if a GPU selection changed it.
    void sync_selection_to_cpu();
    /// primary_centroid_ from primary_flags_ (summed over renderers by the hooks, if set).
    void set_primary_centroid();

    const gl::ShaderLibrary& shaders_;
    int width_, height_;
    ModelFrame frame_;
    GridLayout layout_;
    const grid::CornerPointGrid& grid_;
    ActiveCellRank compact_of_cell_;  ///< Eclipse -> compact, once the layout's table is released
    GridBuffers buffers_;
    CameraBlocks cameras_;  ///< the per-frame camera blocks every pass binds (common/cameras.glsl)
    VisibleFaces visible_;
    std::optional<ExposedSurface> exposed_;  ///< the plain frame's faces, built on its first use
    GpuPrimarySelection selection_;
    PrimaryCentroid centroid_;
    bool secondary_list_built_ = false;
    FacesDrawn last_drawn_;
    bool visible_used_ = false;  ///< the last frame's stage 2 used the culling pass
    std::size_t frames_redrawn_ = 0;
    gl::Texture colour_map_;
    ColourBarLabel label_;
    /// The selection on the CPU for frustum-clusters (it groups the flags) and the full secondary
    /// list, read back from the GPU at the first frame that needs it after select_range.
    std::vector<std::uint8_t> primary_flags_;
    glm::vec3 primary_centroid_{0};                 ///< render space, mean of the primary cells' centres
    std::optional<glm::vec3> cone_reference_;       ///< set_cone_reference
    std::uint64_t primaries_of_all_renderers_ = 0;  ///< summed by the hooks, with the centroid
    const std::uint64_t auto_sweep_from_;            ///< auto_sweep_from_primaries of this context's GL_RENDERER
    bool selection_on_cpu_ = false;
    std::size_t cut_readback_bytes_ = 0;
    std::size_t selection_readback_bytes_ = 0;  ///< RendererStatus::selection_readback_bytes
    std::uint64_t selection_generation_ = 0;  ///< counts selection changes
    std::size_t uploaded_bytes_ = 0;          ///< RendererStatus::uploaded_bytes
    CutTargets cut_;  ///< the strategy's depth; the surface stage 2 reads, resolved from it or from its mean-filtered copy
    RearShellDepth rear_shell_;
    SceneTargets scene_;
    PostTargets post_;
    SecondaryPass secondary_;
    PrimaryPass primary_;
    MeanFilter mean_filter_;
    CutResolve cut_resolve_;
    VolumeCut volume_cut_;
    OpeningCut opening_cut_;
    Ssao ssao_;
    Composite composite_;
    ColourBar colour_bar_;
    WellTubes wells_;
    WellLabels well_labels_;
    FrameCaption frame_caption_;
    gl::VertexArray empty_vertex_array_;
    std::vector<std::pair<std::string, std::unique_ptr<CutSurfaceStrategy>>> strategies_;
    std::optional<Camera> frozen_camera_;
    bool frozen_valid_ = false;
    gl::StageTimer timer_;
    FrameHooks hooks_;
    FramePlan last_plan_;
};

/// Largest image side the current context can render (GL_MAX_TEXTURE_SIZE, GL_MAX_VIEWPORT_DIMS).
int max_image_side();

}  // namespace cutaway::pipeline
