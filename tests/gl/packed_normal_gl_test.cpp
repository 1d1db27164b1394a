// shaders/common/packed_normal.glsl, which the scene's RG32UI targets use for normals (the
// octahedral map in two 16-bit snorms) beside a float kept bit for bit: round trips on the GPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <span>
#include <vector>

#include "gl/compute_dispatch.h"
#include "gl/shader_library.h"
#include "gl/uniforms.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

/// A shader root holding the real shaders/common and one test kernel that packs and unpacks each
/// vec4 of a buffer in place (xyz: a unit normal, w: the float carried beside it).
std::filesystem::path round_trip_shader_root() {
    const std::filesystem::path root = std::filesystem::temp_directory_path() / "cutaway-packed-normal-test";
    std::filesystem::create_directories(root);
    const std::filesystem::path common = root / "common";
    if (!std::filesystem::exists(common)) std::filesystem::create_directory_symlink(gl::ShaderLibrary::default_root() / "common", common);
    std::ofstream(root / "round_trip.comp") << R"(#version 450 core
layout(local_size_x = 64) in;
#include "common/packed_normal.glsl"
layout(std430, binding = 0) buffer Values { vec4 values[]; };
uniform uint count;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= count) return;
    uvec2 words = pack_normal_and(values[i].xyz, values[i].w);
    values[i] = vec4(packed_normal(words), packed_value(words));
}
)";
    return root;
}

TEST(PackedNormal, RoundTripsWithinATenThousandthOfARadianAndKeepsTheFloat) {
    // Random unit normals (uniform on the sphere) and the octahedral map's special places: the
    // axes, the edges of the fold (z = 0) and the fold's corners. The bound: a 16-bit snorm step
    // is 1/32767 of the octahedral square's half-side, so each coordinate is off by at most half
    // of it, and the map stretches distances by at most about 3 near the fold: 6.4e-5 radian at
    // most over 2M random normals in a double-precision model of the same arithmetic; 1e-4
    // leaves room for the GPU's float rounding. The float beside it must come back bit for bit.
    std::mt19937 random(17);
    std::normal_distribution<float> gaussian;
    std::uniform_real_distribution<float> value(-1.0e6f, 1.0e6f);
    std::vector<float> values;
    const auto add = [&](float x, float y, float z, float w) {
        const float length = std::sqrt(x * x + y * y + z * z);
        values.insert(values.end(), {x / length, y / length, z / length, w});
    };
    for (int i = 0; i < 200000; ++i) add(gaussian(random), gaussian(random), gaussian(random), value(random));
    for (const float s : {1.0f, -1.0f}) {
        add(s, 0, 0, 0.0f);
        add(0, s, 0, 1.0f);
        add(0, 0, s, 3.5f);
        add(s, s, 0, 1e-30f);
        add(s, -s, 0, -7.0f);
        add(s, 1e-7f, -1e-7f, 42.0f);
    }
    const std::vector<float> original = values;
    const std::size_t count = values.size() / 4;

    const gl::ShaderLibrary library(round_trip_shader_root());
    const gl::Program program = library.build({{GL_COMPUTE_SHADER, "round_trip.comp"}});
    const gl::Buffer buffer = gl::Buffer::from(std::span<const float>(values));
    buffer.bind_base(GL_SHADER_STORAGE_BUFFER, 0);
    gl::set_uniform(program, "count", unsigned(count));
    program.use();
    glDispatchCompute(gl::group_count(int(count), 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(values.size() * sizeof(float)), values.data());

    double largest_angle = 0;
    std::size_t floats_changed = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const float* a = &original[4 * i];
        const float* b = &values[4 * i];
        // atan2(|a x b|, a . b): acos of a dot product near 1 would turn float rounding of the
        // inputs (1e-7) into angles of 5e-4.
        const double dot = double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2];
        const double cx = double(a[1]) * b[2] - double(a[2]) * b[1], cy = double(a[2]) * b[0] - double(a[0]) * b[2],
                     cz = double(a[0]) * b[1] - double(a[1]) * b[0];
        largest_angle = std::max(largest_angle, std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot));
        if (std::memcmp(&a[3], &b[3], sizeof(float)) != 0) ++floats_changed;
    }
    EXPECT_LE(largest_angle, 1e-4);
    EXPECT_GT(largest_angle, 0.0) << "vacuous: no normal was quantised";
    EXPECT_EQ(floats_changed, 0u);
}

}  // namespace
}  // namespace cutaway::test
