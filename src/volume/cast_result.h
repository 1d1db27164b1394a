#pragma once
// A rendered volume frame from either caster.
#include <cstdint>

#include "gl/image.h"

namespace cutaway::volume {

struct CastResult {
    gl::RgbaImage image;          ///< width x height, rows top to bottom
    std::uint64_t samples = 0;    ///< volume samples classified and composited, all rays
    std::uint64_t rays = 0;       ///< pixels whose ray hit the cube
};

}  // namespace cutaway::volume
