#include "cutaway/cut_surface/opening_cut.h"

#include <bit>
#include <span>
#include <stdexcept>

#include "cutaway/cut_surface/cell_boxes.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

OpeningCut::OpeningCut(const gl::ShaderLibrary& shaders, const ModelFrame& frame)
    : program_(build_cell_box_program(shaders, {.opening = true})),
      seed_program_(build_cell_box_program(shaders, {.back_face_only = true, .opening = true})) {
    for (const gl::Program* p : {&program_, &seed_program_}) {
        gl::set_uniform(*p, "model_min", frame.render_min);
        gl::set_uniform(*p, "model_max", frame.render_max);
    }
}

void OpeningCut::set_cells(const std::vector<CompactOpening>& cells) {
    std::vector<std::uint32_t> packed;
    packed.reserve(2 * cells.size());
    constexpr std::uint32_t beside_bit = 1u << 31;  // frustum.vert (OPENING); compact indices stay below it
    for (const CompactOpening& cell : cells) {
        if (cell.compact_cell >= beside_bit) throw std::invalid_argument("opening cell: compact index above 2^31");
        packed.insert(packed.end(), {cell.compact_cell | (cell.beside_cut ? beside_bit : 0u), std::bit_cast<std::uint32_t>(cell.opening)});
    }
    count_ = cells.size();
    cells_ = packed.empty() ? gl::Buffer() : gl::Buffer::from(std::span<const std::uint32_t>(packed));
}

void OpeningCut::draw(const CutSurfaceInputs& inputs, const CutTargets& targets) const {
    if (!empty()) draw_opening_boxes(program_, inputs, targets.framebuffer, {cells_, count_});
}

void OpeningCut::draw_seeds(const CutSurfaceInputs& inputs, const gl::Framebuffer& seeds) const {
    if (!empty()) draw_opening_boxes(seed_program_, inputs, seeds, {cells_, count_});
}

}  // namespace cutaway::pipeline
