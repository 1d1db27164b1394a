#pragma once
// Peak signal-to-noise ratio between two RGBA images (GPU vs CPU caster, naive vs skipping).
#include "gl/image.h"

namespace cutaway::volume {

/// 10 log10(255^2 / MSE) over the R, G, B channels of equally sized images, in dB; +infinity for
/// identical images. Throws std::invalid_argument when the sizes differ.
double psnr_db(const gl::RgbaImage& a, const gl::RgbaImage& b);

}  // namespace cutaway::volume
