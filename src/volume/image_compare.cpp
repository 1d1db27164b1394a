#include "volume/image_compare.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace cutaway::volume {

double psnr_db(const gl::RgbaImage& a, const gl::RgbaImage& b) {
    if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size())
        throw std::invalid_argument("psnr: images of " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                    " and " + std::to_string(b.width) + "x" + std::to_string(b.height) + " differ in size");
    double squared = 0;
    for (std::size_t k = 0; k < a.pixels.size(); ++k) {
        if (k % 4 == 3) continue;
        const double d = double(a.pixels[k]) - double(b.pixels[k]);
        squared += d * d;
    }
    const double mse = squared / (double(a.pixels.size()) * 0.75);
    if (mse == 0) return std::numeric_limits<double>::infinity();
    return 10 * std::log10(255.0 * 255.0 / mse);
}

}  // namespace cutaway::volume
