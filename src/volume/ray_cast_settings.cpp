#include "volume/ray_cast_settings.h"

#include <stdexcept>
#include <string>

namespace cutaway::volume {

namespace {
void require(bool ok, const char* field, const std::string& expected, double value) {
    if (!ok) throw std::invalid_argument(std::string("volume: ") + field + " = " + std::to_string(value) + ", expected " + expected);
}
}  // namespace

void validate(const RayCastSettings& s) {
    require(s.width >= 16 && s.width <= 8192, "width", "16..8192 pixels", s.width);
    require(s.height >= 16 && s.height <= 8192, "height", "16..8192 pixels", s.height);
    require(s.step > 0.01f && s.step <= 16, "step", "0.01 < step <= 16 voxels", s.step);
    require(s.time_scale >= 0, "time_scale", ">= 0 (0: automatic)", s.time_scale);
    require(s.camera.distance >= 0, "camera distance", ">= 0 (0: frame the cube)", s.camera.distance);
    require(s.camera.elevation_deg > -90 && s.camera.elevation_deg < 90, "camera elevation", "-90 < el < 90 degrees",
            s.camera.elevation_deg);
    require(s.camera.fov_deg > 1 && s.camera.fov_deg < 170, "field of view", "1..170 degrees", s.camera.fov_deg);
    require(s.early_termination_alpha > 0 && s.early_termination_alpha <= 1, "early_termination_alpha", "0 < a <= 1",
            s.early_termination_alpha);
    require(s.block_size >= 2 && s.block_size <= 64, "block_size", "2..64 voxels", s.block_size);
    require(s.reserved_right_px >= 0 && s.reserved_right_px <= 0.5f * float(s.width), "reserved_right_px",
            "0..width/2 pixels", s.reserved_right_px);
    require(s.reserved_left_px >= 0 && s.reserved_left_px <= 0.25f * float(s.width), "reserved_left_px",
            "0..width/4 pixels", s.reserved_left_px);
    require(s.text_height_px >= 0 && s.text_height_px <= 200, "text_height_px", "0..200 pixels", s.text_height_px);
}

}  // namespace cutaway::volume
