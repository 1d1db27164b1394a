#pragma once
// Errors of the GL layer: no context, shader compile/link failures, framebuffer problems.
#include <stdexcept>
#include <string>

namespace cutaway::gl {

/// Thrown for every failure the GL layer cannot recover from; the message names the object
/// (shader file, context platform, framebuffer) and what was expected.
class GlError : public std::runtime_error {
public:
    explicit GlError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace cutaway::gl
