#include "distributed/scene_compositor.h"

#include <IceT.h>
#include <IceTMPI.h>
#include <mpi.h>

#include <bit>
#include <chrono>
#include <cfloat>
#include <stdexcept>

#include "gl/texture_readback.h"

namespace cutaway::distributed {
namespace {

void check_icet(const char* what) {
    if (const IceTEnum error = icetGetError(); error != ICET_NO_ERROR)
        throw std::runtime_error(std::string("IceT: ") + what + " failed (error 0x" + std::to_string(error) + ")");
}

template <typename T>
void write_texture(const gl::Texture& texture, GLenum format, GLenum type, const std::vector<T>& values) {
    glTextureSubImage2D(texture.id(), 0, 0, 0, texture.width(), texture.height(), format, type, values.data());
}

}  // namespace

struct SceneCompositor::Impl {
    int rank = 0;
    IceTCommunicator communicator = nullptr;
    IceTContext context = nullptr;
    // This rank's buffers, then (rank 0) the composited ones.
    std::vector<float> depth, normal_depth, packed, shell;
    std::vector<std::uint8_t> colour;
    std::vector<std::uint32_t> normal_depth_words, id_pairs, ids;
    std::size_t icet_bytes = 0, reduce_bytes = 0;
    double exchange_ms = 0, wait_ms = 0;

    /// One Z-buffer composite of an RGBA32F buffer keyed by `depth`; at rank 0 `colour_out`
    /// (and, when given, `depth_out`) receive the result.
    void composite(const std::vector<float>& rgba, std::vector<float>& colour_out, std::vector<float>* depth_out) {
        const IceTFloat background[4] = {0, 0, 0, 0};
        const IceTImage image = icetCompositeImage(rgba.data(), depth.data(), nullptr, nullptr, nullptr, background);
        check_icet("icetCompositeImage");
        IceTInt sent = 0;
        icetGetIntegerv(ICET_BYTES_SENT, &sent);
        icet_bytes += std::size_t(sent);
        if (rank != 0) return;
        colour_out.resize(rgba.size());
        icetImageCopyColorf(image, colour_out.data(), ICET_IMAGE_COLOR_RGBA_FLOAT);
        if (depth_out) {
            depth_out->resize(depth.size());
            icetImageCopyDepthf(image, depth_out->data(), ICET_IMAGE_DEPTH_FLOAT);
        }
        check_icet("copying the composited image");
    }
};

SceneCompositor::SceneCompositor(int width, int height) : impl_(std::make_unique<Impl>()) {
    MPI_Comm_rank(MPI_COMM_WORLD, &impl_->rank);
    impl_->communicator = icetCreateMPICommunicator(MPI_COMM_WORLD);
    impl_->context = icetCreateContext(impl_->communicator);
    icetDiagnostics(ICET_DIAG_ERRORS | ICET_DIAG_ALL_NODES);
    icetCompositeMode(ICET_COMPOSITE_MODE_Z_BUFFER);
    icetSetColorFormat(ICET_IMAGE_COLOR_RGBA_FLOAT);
    icetSetDepthFormat(ICET_IMAGE_DEPTH_FLOAT);
    icetStrategy(ICET_STRATEGY_SEQUENTIAL);  // one tile: straight to the single-image strategy
    icetSingleImageStrategy(ICET_SINGLE_IMAGE_STRATEGY_RADIXK);
    icetDisable(ICET_COMPOSITE_ONE_BUFFER);  // keep the composited depth
    icetResetTiles();
    icetAddTile(0, 0, width, height, 0);
    check_icet("setting up the context");
}

SceneCompositor::~SceneCompositor() {
    icetDestroyContext(impl_->context);
    icetDestroyMPICommunicator(impl_->communicator);
}

bool SceneCompositor::composite(const pipeline::SceneTargets& scene, const std::vector<std::uint32_t>& whole_ids) {
    Impl& m = *impl_;
    icetSetContext(m.context);
    gl::read_texels_into(scene.depth, GL_DEPTH_COMPONENT, GL_FLOAT, 1, m.depth);
    gl::read_texels_into(scene.normal_depth, GL_RG_INTEGER, GL_UNSIGNED_INT, 2, m.normal_depth_words);
    gl::read_texels_into(scene.colour, GL_RGBA, GL_UNSIGNED_BYTE, 4, m.colour);
    gl::read_texels_into(scene.id, GL_RG_INTEGER, GL_UNSIGNED_INT, 2, m.id_pairs);
    gl::read_texels_into(scene.shell_depth, GL_RED, GL_FLOAT, 1, m.shell);
    const std::size_t pixels = m.depth.size();
    if (whole_ids.size() != pixels) throw std::invalid_argument("composite: one whole-model id per pixel expected");
    // Integers below 2^24 are exact in float, and Z-buffer compositing copies them unchanged.
    m.packed.resize(4 * pixels);
    m.normal_depth.resize(4 * pixels);
    for (std::size_t p = 0; p < pixels; ++p) {
        // The packed normal's two 16-bit halves (exact in float) and the linear depth itself.
        const std::uint32_t normal = m.normal_depth_words[2 * p];
        m.normal_depth[4 * p + 0] = float(normal & 0xffffu);
        m.normal_depth[4 * p + 1] = float(normal >> 16);
        m.normal_depth[4 * p + 2] = 0.0f;
        m.normal_depth[4 * p + 3] = std::bit_cast<float>(m.normal_depth_words[2 * p + 1]);
        const std::uint8_t* c = &m.colour[4 * p];
        m.packed[4 * p + 0] = float(std::uint32_t(c[0]) | std::uint32_t(c[1]) << 8 | std::uint32_t(c[2]) << 16);
        m.packed[4 * p + 1] = float(whole_ids[p] & 0xffffu);
        m.packed[4 * p + 2] = float(whole_ids[p] >> 16);
        m.packed[4 * p + 3] = float(m.id_pairs[2 * p + 1]);
    }
    // The uncut shell's nearest face: background (0) must lose a minimum.
    for (float& s : m.shell)
        if (s == 0.0f) s = FLT_MAX;

    const auto waited = std::chrono::steady_clock::now();
    MPI_Barrier(MPI_COMM_WORLD);
    const auto started = std::chrono::steady_clock::now();
    m.wait_ms = std::chrono::duration<double, std::milli>(started - waited).count();
    m.icet_bytes = 0;
    std::vector<float> normal_depth_out, packed_out, depth_out, shell_out(m.rank == 0 ? pixels : 0);
    m.composite(m.normal_depth, normal_depth_out, &depth_out);
    m.composite(m.packed, packed_out, nullptr);
    MPI_Reduce(m.shell.data(), shell_out.data(), int(pixels), MPI_FLOAT, MPI_MIN, 0, MPI_COMM_WORLD);
    m.reduce_bytes = m.rank == 0 ? 0 : pixels * sizeof(float);
    m.exchange_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    if (m.rank != 0) return false;

    m.ids.assign(pixels, 0);
    for (std::size_t p = 0; p < pixels; ++p) {
        const float* q = &packed_out[4 * p];
        const auto rgb = std::uint32_t(q[0]);
        m.colour[4 * p + 0] = std::uint8_t(rgb & 0xffu);
        m.colour[4 * p + 1] = std::uint8_t(rgb >> 8 & 0xffu);
        m.colour[4 * p + 2] = std::uint8_t(rgb >> 16 & 0xffu);
        m.ids[p] = std::uint32_t(q[1]) | std::uint32_t(q[2]) << 16;
        m.colour[4 * p + 3] = m.ids[p] != 0 ? 255 : 0;
        m.id_pairs[2 * p] = m.ids[p];
        m.id_pairs[2 * p + 1] = std::uint32_t(q[3]);
        if (shell_out[p] == FLT_MAX) shell_out[p] = 0.0f;
        const float* n = &normal_depth_out[4 * p];
        m.normal_depth_words[2 * p] = std::uint32_t(n[0]) | std::uint32_t(n[1]) << 16;
        m.normal_depth_words[2 * p + 1] = std::bit_cast<std::uint32_t>(n[3]);
    }
    write_texture(scene.depth, GL_DEPTH_COMPONENT, GL_FLOAT, depth_out);
    write_texture(scene.normal_depth, GL_RG_INTEGER, GL_UNSIGNED_INT, m.normal_depth_words);
    write_texture(scene.colour, GL_RGBA, GL_UNSIGNED_BYTE, m.colour);
    write_texture(scene.id, GL_RG_INTEGER, GL_UNSIGNED_INT, m.id_pairs);
    write_texture(scene.shell_depth, GL_RED, GL_FLOAT, shell_out);
    return true;
}

bool SceneCompositor::displays() const { return impl_->rank == 0; }

const std::vector<std::uint32_t>& SceneCompositor::composited_ids() const { return impl_->ids; }
std::size_t SceneCompositor::icet_bytes_sent() const { return impl_->icet_bytes; }
std::size_t SceneCompositor::reduce_bytes_sent() const { return impl_->reduce_bytes; }
double SceneCompositor::last_exchange_ms() const { return impl_->exchange_ms; }
double SceneCompositor::last_wait_ms() const { return impl_->wait_ms; }

}  // namespace cutaway::distributed
