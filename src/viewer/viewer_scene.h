#pragma once
// The model on screen: grid, chosen property, primary cells and the cutaway renderer drawing
// them. The renderer is rebuilt for edited shaders (a new size only resizes its targets,
// CutawayRenderer::resize); the selection survives.
#include <memory>
#include <optional>

#include "app_core/model_source.h"
#include "app_core/render_options.h"
#include "cutaway/cutaway_renderer.h"
#include "gl/shader_library.h"
#include "viewer/property_histogram.h"
#include "viewer/step_player.h"

namespace cutaway::viewer {

class ViewerScene {
public:
    /// Chooses the property and primaries of `options` and builds a renderer of `width` x `height`.
    /// Throws like `cutaway render` does for bad options (std::invalid_argument) or GL failures.
    ViewerScene(app::LoadedModel model, const gl::ShaderLibrary& shaders, const app::RenderOptions& options,
                int width, int height);

    /// Re-chooses property, step and primaries from `options` (throws std::invalid_argument and
    /// keeps the previous selection for a bad one).
    void select(const app::RenderOptions& options);
    /// A new renderer of `width` x `height` with the current selection. Reads the shader files
    /// again and compiles the programs the frame uses, so it also reloads edited shaders. Throws
    /// gl::GlError (and keeps the previous renderer) when a shader does not compile.
    void rebuild_renderer(int width, int height, const pipeline::FrameSettings& settings);

    pipeline::CutawayRenderer& renderer() { return *renderer_; }
    const grid::CornerPointGrid& grid() const { return model_.grid; }
    const std::string& description() const { return model_.description; }
    const app::PropertyChoice& property() const { return property_; }
    /// The cut volumes drawn (--cut-volume/--cut-volumes, then as edited).
    const std::vector<volumes::CutVolume>& cut_volumes() const { return cut_volumes_->volumes; }
    /// Replaces the cut volumes (throws std::invalid_argument naming the volume; the old ones stay).
    void set_cut_volumes(const std::vector<volumes::CutVolume>& list);
    /// The wells a `well:` volume can cut around, by name.
    std::vector<std::string> well_names() const;
    /// The model's bounds in model coordinates (where new volumes are placed).
    const grid::Box3& bounds() const { return bounds_; }
    std::size_t primary_count() const;
    const PropertyHistogram& histogram() const { return histogram_; }
    /// Time steps of the property shown (0 for a static one).
    std::size_t step_count() const;
    /// A simulator case's report steps with their dates (empty for other models).
    const std::vector<eclipse::ReportStep>& report_steps() const;

    /// A player of the shown property's steps from `start_step`, with the shown primary range and
    /// `animate`'s default hysteresis; fixes the colour scale the played frames use (reads every
    /// step once unless --colour-range gives it). Throws std::invalid_argument for a static property.
    std::unique_ptr<StepPlayer> player(temporal::Coherence coherence, std::size_t frames_per_step, std::size_t start_step);
    /// Shows a played frame: its values on the shown property's colour range (when they changed)
    /// and its primaries.
    void show(const temporal::CoherentSequence::Frame& frame);

private:
    void apply_selection(pipeline::CutawayRenderer& renderer) const;
    void apply_colouring(pipeline::CutawayRenderer& renderer) const;
    void select_primaries(pipeline::CutawayRenderer& renderer) const;

    app::LoadedModel model_;
    const gl::ShaderLibrary& shaders_;
    double z_scale_;
    app::PropertyChoice property_;
    std::optional<grid::IjkBox> box_;
    bool primaries_ = true;  ///< false: --primaries none
    app::CutVolumeOptions volume_options_;
    std::size_t memory_limit_bytes_ = 0;
    grid::Box3 bounds_;
    std::optional<app::CutVolumeSet> cut_volumes_;  ///< built with the first renderer (its frame)
    std::vector<float> options_colour_range_;      ///< --colour-range of the last selection (empty: none)
    annotation::ColourBarLabel playing_colours_;   ///< the played frames' colour scale (player())
    PropertyHistogram histogram_;
    std::unique_ptr<pipeline::CutawayRenderer> renderer_;
    pipeline::WellSet wells_;  ///< --wells at the report step shown
    volumes::WellPaths volume_wells_;  ///< every well's path at the first step read, for `well:` volumes
    std::vector<std::string> wells_values_;  ///< the --wells values wells_ was read with
    int wells_step_ = -2;      ///< the step wells_ belongs to (-2: none read yet)
};

/// Bins of the histogram drawn under the range sliders.
inline constexpr int histogram_bins = 64;

}  // namespace cutaway::viewer
