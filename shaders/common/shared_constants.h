// Names and numbers C++ and GLSL share, defined once: shaders include it through the shader
// library ("common/shared_constants.h"), C++ with shaders/ on its include path. No other #include
// may appear here (the shader library would try to inline it).
#ifndef CUTAWAY_SHARED_CONSTANTS_H
#define CUTAWAY_SHARED_CONSTANTS_H

#ifdef __cplusplus
namespace cutaway::shared {
using uint = unsigned int;
#define CUTAWAY_SHARED_CONST inline constexpr
#else
#define CUTAWAY_SHARED_CONST const
#endif

// Flags stages 2 and 3 keep per pixel (the scene id target's second channel,
// src/cutaway/frame_targets.h); the image metrics read them back (src/metrics/image_metrics.h).
CUTAWAY_SHARED_CONST uint flag_primary = 1u;
CUTAWAY_SHARED_CONST uint flag_cut_fill = 2u;    // a cell's inside seen through the cut
CUTAWAY_SHARED_CONST uint flag_border = 4u;      // border line where a face meets the cut
CUTAWAY_SHARED_CONST uint flag_edge = 8u;        // cell edge line
CUTAWAY_SHARED_CONST uint flag_shell_cut = 16u;  // border line on a shell face
// Cut fill showing the cut surface itself (not a shell face where the cut is clamped to the rear
// shell): the pixel's stored depth is its cell's far face, the surface seen is the cut's
// (post/ssao.comp takes the cut's depth there).
CUTAWAY_SHARED_CONST uint flag_shows_cut = 64u;
// A well tube (stage 3, primary/well.frag): its pixel shows no cell (id 0), and the flags' bits
// from well_index_shift up hold the well's index in the renderer's well set. The distributed
// compositor carries flags as floats, exact below 2^24: at most max_drawn_wells wells.
CUTAWAY_SHARED_CONST uint flag_well = 32u;
CUTAWAY_SHARED_CONST uint well_index_shift = 8u;
CUTAWAY_SHARED_CONST uint max_drawn_wells = 65535u;

// Shader storage buffer binding points: C++ binds each buffer at its name, the shader declares
// its block there (layout(std430, binding = NAME)). Passes that never run together share points
// (the primary selection's with the culling's), each under its own name.
CUTAWAY_SHARED_CONST uint ssbo_faces = 3u;               // face records drawn (common/face.vert)
CUTAWAY_SHARED_CONST uint ssbo_face_corners = 4u;        // exposed surface's stored corners
CUTAWAY_SHARED_CONST uint ssbo_primary_cells = 5u;       // primary cells (frustums, centroid)
CUTAWAY_SHARED_CONST uint ssbo_opening_cells = 6u;       // cells opening their cut (frustum.vert OPENING)
CUTAWAY_SHARED_CONST uint ssbo_brick_begin = 7u;         // culling: first cell of each brick
CUTAWAY_SHARED_CONST uint ssbo_brick_boxes = 8u;         // culling: bricks' bounds
CUTAWAY_SHARED_CONST uint ssbo_cell_face_classes = 9u;   // per cell, its faces' classes
CUTAWAY_SHARED_CONST uint ssbo_primary_bits = 10u;       // one bit per active cell
CUTAWAY_SHARED_CONST uint ssbo_culling_counters = 11u;   // culling's counts
CUTAWAY_SHARED_CONST uint ssbo_visible_faces = 12u;      // culling's output faces
CUTAWAY_SHARED_CONST uint ssbo_cut_pyramid = 13u;        // the cut's depth pyramid
CUTAWAY_SHARED_CONST uint ssbo_draw_commands = 14u;      // culling's indirect draws
CUTAWAY_SHARED_CONST uint ssbo_brick_classes = 15u;      // culling: bricks in front of / behind the cut
CUTAWAY_SHARED_CONST uint ssbo_active_words = 15u;       // selection: active-cell bit words
CUTAWAY_SHARED_CONST uint ssbo_cell_face_masks = 16u;    // culling: faces kept per cell
CUTAWAY_SHARED_CONST uint ssbo_word_counts = 16u;        // selection: primaries per word
CUTAWAY_SHARED_CONST uint ssbo_brick_face_counts = 17u;  // culling: faces kept per brick
CUTAWAY_SHARED_CONST uint ssbo_selection_totals = 17u;   // selection: primary cell and face totals
CUTAWAY_SHARED_CONST uint ssbo_brick_offsets = 18u;      // culling: each brick's first output face
CUTAWAY_SHARED_CONST uint ssbo_primary_cells_out = 18u;  // selection: the primary cells written
CUTAWAY_SHARED_CONST uint ssbo_block_offsets = 19u;      // culling: each block's first output face
CUTAWAY_SHARED_CONST uint ssbo_primary_faces_out = 19u;  // selection: the primary faces written
CUTAWAY_SHARED_CONST uint ssbo_centroid_partial_sums = 20u;  // primary centroid's partial sums

// Texture units of the samplers shaders declare at a fixed binding (layout(binding = NAME));
// passes that never run together share units, each under its own name.
CUTAWAY_SHARED_CONST uint tex_nearest_face = 7u;      // stage 2: face index left by nearest_face.frag
CUTAWAY_SHARED_CONST uint tex_pillars = 8u;           // grid: pillar coordinates
CUTAWAY_SHARED_CONST uint tex_corner_depths = 9u;     // grid: corner depths
CUTAWAY_SHARED_CONST uint tex_cells = 10u;            // grid: compact cells
CUTAWAY_SHARED_CONST uint tex_cell_values = 11u;      // grid: the colouring's values
CUTAWAY_SHARED_CONST uint tex_face_classes = 12u;     // culling: faces' classes
CUTAWAY_SHARED_CONST uint tex_cluster_ranges = 12u;   // frustum clusters: each cluster's cells
CUTAWAY_SHARED_CONST uint tex_primary_bits = 13u;     // culling: one bit per active cell
CUTAWAY_SHARED_CONST uint tex_cluster_cells = 13u;    // frustum clusters: the cells
CUTAWAY_SHARED_CONST uint tex_brick_cells = 14u;      // culling: cells by brick
CUTAWAY_SHARED_CONST uint tex_stored_corners = 14u;   // exposed surface: stored face corners
CUTAWAY_SHARED_CONST uint tex_brick_begin = 15u;      // culling: first cell of each brick
CUTAWAY_SHARED_CONST uint tex_brick_classes = 16u;    // culling: bricks' classes

// Image units (at most 8: GL_MAX_IMAGE_UNITS on NVIDIA). The scene targets (src/cutaway/frame_targets.h)
// as stage 2's compute passes (secondary/raycast_borders.comp, deferred_shading.comp) and the
// post passes (post/ssao.comp, composite.comp) read and write them:
CUTAWAY_SHARED_CONST uint img_scene_colour = 0u;        // lit colour (RGBA8)
CUTAWAY_SHARED_CONST uint img_scene_id = 1u;            // compact cell + 1, pixel flags (RG32UI)
CUTAWAY_SHARED_CONST uint img_scene_face_plane = 2u;    // world face normal and depth or face class (RG32UI)
CUTAWAY_SHARED_CONST uint img_scene_normal_depth = 3u;  // eye normal, linear depth (RG32UI)
// The cut's images that several shaders read (common/cut_lookup.glsl CUT_IMAGES) or
// cut_surface/cut_normals.comp writes:
CUTAWAY_SHARED_CONST uint img_cut_surface = 4u;     // the resolved cut's depth (R32F)
CUTAWAY_SHARED_CONST uint img_cut_rear_clamp = 5u;  // 1 where the cut is clamped at the rear shell (R8)
CUTAWAY_SHARED_CONST uint img_cut_normals = 6u;     // the cut's world normals (RGBA32F)
// The post passes' own, which never run with the cut's images bound (they share its units):
CUTAWAY_SHARED_CONST uint img_post_ambient = 4u;       // SSAO factor, linear depth (RG32F)
CUTAWAY_SHARED_CONST uint img_post_shell_depth = 5u;   // the uncut shell's linear depth (R32F)
CUTAWAY_SHARED_CONST uint img_post_final_colour = 6u;  // the composited frame (RGBA8)
CUTAWAY_SHARED_CONST uint img_post_cut_depth = 7u;     // SSAO: the cut's depth where the cut fill shows it (R32F)

// Uniform block binding points of the per-frame cameras (common/cameras.glsl,
// src/cutaway/camera_blocks.h).
CUTAWAY_SHARED_CONST uint ubo_view_camera = 0u;  // the camera a pass rasterises with
CUTAWAY_SHARED_CONST uint ubo_cut_camera = 1u;   // the camera whose cut image a pass reads

#undef CUTAWAY_SHARED_CONST
#ifdef __cplusplus
}  // namespace cutaway::shared
#endif

#endif
