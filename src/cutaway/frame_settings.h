#pragma once
// Every switch of one cutaway frame, with the paper's defaults (SPEC.md section 2). A run's
// stats.json prints the options they come from (RenderOptions::describe).
#include <string>

namespace cutaway::pipeline {

enum class BorderMode { raycast, threshold };
enum class MeanFilterKernel { full, sampled, distance_scaled };  ///< post/mean_filter.h
enum class OnlyLayer { both, primaries, secondaries };
/// Seeds of the cone-field strategies: each primary's box back face (widened by a pixel) or the
/// primaries' own faces (the exact rear hull of the cells).
enum class SeedSource { boxes, geometry };
/// Stage 2's faces: `visible` (a GPU culling pass picks the faces that can reach a pixel, SPEC.md
/// section 6) or `all_faces` (every face of every secondary cell, the paper's path).
enum class DrawMode { visible, all_faces };
/// Stage 2's passes on the visible path: `deferred` (the default) = the draw makes the cut test
/// only and leaves the nearest kept fragment's cell, face and edge line, then a compute pass shades
/// each visible pixel once (secondary/deferred_shading.comp); `one` = every fragment shaded, as
/// all-faces draws; `two` = the cut test and depth first (secondary/nearest_face.frag), then the
/// faces drawn again, shading once per pixel (on llvmpipe the second draw's triangle set-up costs
/// about what it saves; README, issue 14).
enum class Stage2Passes { one, two, deferred };
/// How property values map onto the colour map: `automatic` = logarithmic for permeabilities
/// (names starting with PERM, spread over decades), linear otherwise.
enum class ColourScale { automatic, linear, log };

struct FrameSettings {
    /// Cut-surface strategy (cut_surface_registry.h), or "auto" (the default, cut_strategy_choice.h):
    /// one frustum per IJK box of adjacent primaries (`frustum-clusters`: the same exposure as the
    /// paper's per-cell `frustum`, a fraction of its cost) below 10,000 primary cells on a GPU and
    /// 500 on a software rasteriser, the frustum union in O(pixels) (`frustum-sweep`) from there;
    /// `frustum` is the paper's one frustum per primary cell (Table 1 uses it).
    std::string strategy = "auto";
    DrawMode draw = DrawMode::visible;
    Stage2Passes stage2_passes = Stage2Passes::deferred;
    SeedSource seeds = SeedSource::boxes;  ///< seeds of the distance-transform strategies
    /// Full opening angles (the paper's aperture), degrees 0..180: each wall leans out by half of
    /// it from the view ray (shaders/cut_surface/frustum.geom); 180: flat walls.
    float aperture_h_deg = 60;
    float aperture_v_deg = 60;
    float back_margin = 0.002f;            ///< back-plane margin, fraction of the model radius
    BorderMode border = BorderMode::raycast;
    float border_width_px = 1;             ///< w, pixels
    float line_width_px = 1;               ///< cell edge lines, pixels
    int mean_filter = 9;                   ///< k x k, 0 or 1 = off
    MeanFilterKernel mean_filter_kernel = MeanFilterKernel::full;
    bool ssao = true;
    int ssao_samples = 16;
    /// Radius and strength chosen so that the occlusion reads at print size: at 0.03 and 1.6 the
    /// SSAO panel of fig. 9 could not be told from the plain one (issue 46; the measured
    /// differences are in the commit that set these).
    float ssao_radius = 0.045f;            ///< fraction of the model radius
    float ssao_strength = 4.0f;            ///< occlusion factor = 1 - strength * mean sample occlusion
    /// The least occlusion factor: a pixel keeps at least this share of its colour. At strength 4
    /// a narrow crevice (a fault's gap seen beside a cut wall) reached 0 and drew black, read as a
    /// crack through the model (issue 46's referee); it stays dark, not black.
    float ssao_min_factor = 0.4f;
    /// true: occlusion computed for one pixel in four and upsampled by depth (post/ssao.comp,
    /// post/composite.comp); false: for every pixel, as the paper.
    bool ssao_half_resolution = true;
    bool saturation = false;
    float saturation_primary = 1.5f;
    float saturation_secondary = 0.35f;
    bool silhouette = false;
    int silhouette_width_px = 4;           ///< band of the doubled line: 1 px, a gap, 1 px
    bool contours = true;                  ///< shell contour lines (stage 3)
    bool hide_internal_lines = false;
    OnlyLayer only = OnlyLayer::both;
    /// false (`--primaries none`): no primary set; the cut is made by the cut volumes alone and
    /// stage 3 draws no primaries.
    bool primaries = true;
    bool cut_enabled = true;               ///< false: no cut at all (the uncut reference frame)
    /// true: the cut may leave the model through its rear shell (background shows through), as
    /// the paper's frustums do; false: clamped to just in front of the farthest shell surface.
    bool see_through = false;
    bool colour_bar = true;
    /// A line of text at the frame's top-left corner (an animation's date and report step);
    /// empty: none (FramePass::caption).
    std::string caption;
    /// Equal depths in stages 2 and 3: the fragment drawn first wins (GL_LESS, the default) or the
    /// one drawn last (GL_LEQUAL). Tests use it to tell draw-order ties from real differences.
    bool depth_ties_to_last = false;
};

/// aperture 180 degrees: both walls flat (the expert request "remove everything in front").
inline void set_aperture_180(FrameSettings& settings) {
    settings.aperture_h_deg = 180;
    settings.aperture_v_deg = 180;
}

const char* to_string(BorderMode mode);
const char* to_string(MeanFilterKernel kernel);
const char* to_string(OnlyLayer only);
const char* to_string(SeedSource seeds);
const char* to_string(DrawMode draw);
const char* to_string(Stage2Passes passes);
const char* to_string(ColourScale scale);

}  // namespace cutaway::pipeline
