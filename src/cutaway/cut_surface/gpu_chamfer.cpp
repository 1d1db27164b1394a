// Chamfer propagation on the GPU, as directional line sweeps instead of the two raster passes.
//
// Method. The raster passes compute h(p) = max over seeds q of t(q) - slope * L(q -> p), L the
// length of the shortest path of mask steps inside the image (cone_field/chamfer.h). For these
// masks the shortest path uses at most two step directions, adjacent in angle (the chamfer ball
// is a convex polygon whose vertices are the steps, and adjacent steps form a lattice basis of
// determinant 1, so the integer optimum is the vertex one): an axial and a diagonal step for the
// 3x3 masks; an axial and a knight, or a knight and a diagonal step for 5x5 (the chessboard
// mask's axial and diagonal steps of length 1 give max(|dx|, |dy|)). A 1-D max-plus dilation
// along every lattice line of one step direction (a forward and a backward sweep, one GPU
// invocation per line) lets a height travel any number of those steps; sweeping every direction
// once, in any order, realises every optimal path: its two segments can be taken in the order
// their directions are swept, and either way the path is monotone in x and y between q and p, so
// it stays inside the image. Every path the sweeps realise is a path of mask steps inside the
// image, so none beats L: the sweeps compute exactly the raster passes' h, in exact arithmetic.
//
// Error bound. Against the CPU reference the only difference is rounding: float in stored units
// here, double in depth units there. A height reaching p went through at most W + H subtractions
// of a weight below 1, each rounded to half an ulp of a value in [-1, 1]: |GPU - CPU| <=
// (W + H) * 2^-24 of (far - near), plus the unit conversions. Against the exact cone the error is
// the mask's length error (chamfer.h): 0 .. +8.24% (1, sqrt 2), -5.72% .. +5.41% <3,4>,
// -1.61% .. +1.98% <5,7,11> of slope x distance.
#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "cutaway/cut_surface/gpu_cone_transform.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {

constexpr int group_size = 64;  // chamfer_sweep.comp's local size

/// A line direction of the sweeps: x > 0, or x == 0 and y > 0 (a step and its negation sweep
/// the same lines); its chamfer length, pixels.
struct SweepDirection {
    glm::ivec2 step;
    double length;
};

/// The mask's directions (the forward half of the mask; any order, see above), the rows' (1, 0)
/// first: chamfer_sweep.comp's INIT variant sweeps it straight from the seed image.
std::vector<SweepDirection> sweep_directions(cone_field::ChamferMask mask) {
    std::vector<SweepDirection> directions;
    for (const cone_field::ChamferStep& s : cone_field::chamfer_forward_steps(mask)) {
        glm::ivec2 step(s.dx, s.dy);
        if (step.x < 0 || (step.x == 0 && step.y < 0)) step = -step;
        directions.push_back({step, s.length});
    }
    const auto rows = std::find_if(directions.begin(), directions.end(), [](const SweepDirection& d) { return d.step == glm::ivec2(1, 0); });
    if (rows == directions.end()) throw std::logic_error("chamfer mask without the axial step (1, 0)");
    std::rotate(directions.begin(), rows, rows + 1);
    return directions;
}

class GpuChamfer final : public GpuConeTransform {
public:
    GpuChamfer(const gl::ShaderLibrary& shaders, cone_field::ChamferMask mask)
        : init_(shaders, "cut_surface/chamfer_sweep.comp"),
          sweep_(shaders.build({{GL_COMPUTE_SHADER, "cut_surface/chamfer_sweep.comp"}})),
          resolve_(shaders.build({{GL_VERTEX_SHADER, "post/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "cut_surface/cone_resolve.frag"}})),
          directions_(sweep_directions(mask)) {}

    void run(const GpuConeInput& in, const CutTargets& targets) override {
        const int width = targets.depth.width(), height = targets.depth.height();
        if (heights_.width() != width || heights_.height() != height) heights_ = gl::Texture(GL_TEXTURE_2D, GL_R32F, width, height);
        glBindImageTexture(0, heights_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32F);

        for (std::size_t k = 0; k < directions_.size(); ++k) {
            const SweepDirection& d = directions_[k];
            const gl::Program& p = k == 0 ? init_.prepare(in) : sweep_;  // the rows, from the seeds
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            const int columns = std::min(d.step.x, width);
            const int lines = columns * height + std::min(std::abs(d.step.y), height) * (width - columns);
            if (k > 0) gl::set_uniform(p, "direction", d.step);
            gl::set_uniform(p, "weight", float(double(in.slope) * d.length));
            gl::set_uniform(p, "line_count", lines);
            p.use();
            glDispatchCompute(group_count(lines, group_size), 1, 1);
        }

        gl::set_uniform(resolve_, "heights", 0);
        heights_.bind(0);
        write_cut_depth(resolve_, targets);
    }

private:
    SeedInitPrograms init_;
    gl::Program sweep_, resolve_;
    std::vector<SweepDirection> directions_;
    gl::Texture heights_;  ///< R32F stored units, resized with the targets
};

}  // namespace

std::unique_ptr<GpuConeTransform> make_gpu_chamfer(const gl::ShaderLibrary& shaders, cone_field::ChamferMask mask) {
    return std::make_unique<GpuChamfer>(shaders, mask);
}

}  // namespace cutaway::pipeline
