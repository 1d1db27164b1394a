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

void CutAllreduce::combine(const gl::Texture& cut_depth, const gl::Texture* rear_shell) {
    const std::size_t pixels = std::size_t(width_) * std::size_t(height_);
    depths_.resize(rear_shell ? 2 * pixels : pixels);
    read_depth(cut_depth, depths_.data(), pixels);
    if (rear_shell) read_depth(*rear_shell, depths_.data() + pixels, pixels);
    message_bytes_ = depths_.size() * sizeof(float);
    const auto waited = std::chrono::steady_clock::now();
    MPI_Barrier(MPI_COMM_WORLD);
    const auto started = std::chrono::steady_clock::now();
    last_wait_ms_ = std::chrono::duration<double, std::milli>(started - waited).count();
    MPI_Allreduce(MPI_IN_PLACE, depths_.data(), int(depths_.size()), MPI_FLOAT, MPI_MAX, MPI_COMM_WORLD);
    last_mpi_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    write_depth(cut_depth, depths_.data(), width_, height_);
    if (rear_shell) write_depth(*rear_shell, depths_.data() + pixels, width_, height_);
}

}  // namespace cutaway::distributed
