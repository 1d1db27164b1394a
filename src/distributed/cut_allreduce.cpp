#include "distributed/cut_allreduce.h"

#include <mpi.h>

#include <chrono>

namespace cutaway::distributed {
namespace {

void read_depth(const gl::Texture& texture, float* out, std::size_t pixels) {
    glGetTextureImage(texture.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(pixels * sizeof(float)), out);
}

void write_depth(const gl::Texture& texture, const float* values, int width, int height) {
    glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, values);
}

}  // namespace

CutAllreduce::CutAllreduce(int width, int height) : width_(width), height_(height) {}

void CutAllreduce::start_frame() {
    message_bytes_ = 0;
    last_mpi_ms_ = last_wait_ms_ = 0;
}

void CutAllreduce::combine(const std::vector<const gl::Texture*>& images) {
    const std::size_t pixels = std::size_t(width_) * std::size_t(height_);
    depths_.resize(images.size() * pixels);
    for (std::size_t i = 0; i < images.size(); ++i) read_depth(*images[i], depths_.data() + i * pixels, pixels);
    message_bytes_ += depths_.size() * sizeof(float);
    const auto waited = std::chrono::steady_clock::now();
    MPI_Barrier(MPI_COMM_WORLD);
    const auto started = std::chrono::steady_clock::now();
    MPI_Allreduce(MPI_IN_PLACE, depths_.data(), int(depths_.size()), MPI_FLOAT, MPI_MAX, MPI_COMM_WORLD);
    const auto finished = std::chrono::steady_clock::now();
    last_wait_ms_ += std::chrono::duration<double, std::milli>(started - waited).count();
    last_mpi_ms_ += std::chrono::duration<double, std::milli>(finished - started).count();
    for (std::size_t i = 0; i < images.size(); ++i) write_depth(*images[i], depths_.data() + i * pixels, width_, height_);
}

void CutAllreduce::sum(std::vector<double>& values) const {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

}  // namespace cutaway::distributed
