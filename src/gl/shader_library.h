#pragma once
// GLSL files under shaders/, with `#include "path"` (relative to the shader root) and typed
// variants turned into #defines placed after the #version line.
#include <filesystem>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "gl/gl_objects.h"

namespace cutaway::gl {

/// One `#define NAME VALUE` (VALUE may be empty).
using ShaderDefine = std::pair<std::string, std::string>;
using ShaderDefines = std::vector<ShaderDefine>;

struct ShaderStage {
    GLenum type;       ///< GL_VERTEX_SHADER, GL_GEOMETRY_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
    std::string file;  ///< path relative to the shader root, e.g. "cutaway/secondary.frag"
};

/// Source text with includes expanded. `files` lists the file of each `#line` source number, so
/// a compiler message "3(12)" can be turned back into a file name.
struct ExpandedSource {
    std::string text;
    std::vector<std::filesystem::path> files;
};

class ShaderLibrary {
public:
    /// `root`: the shaders/ folder. Throws GlError if it does not exist.
    explicit ShaderLibrary(std::filesystem::path root);

    /// The default root: $CUTAWAY_SHADER_DIR if set, else the source tree's shaders/ folder.
    static std::filesystem::path default_root();

    const std::filesystem::path& root() const { return root_; }

    /// Reads `file` and expands its includes (depth at most 16, no cycles); throws GlError naming
    /// the file and line of a missing or cyclic include.
    ExpandedSource expand(const std::string& file, const ShaderDefines& defines = {}) const;

    /// Compiles and links the stages; throws GlError with the info log and file names on failure.
    Program build(const std::vector<ShaderStage>& stages, const ShaderDefines& defines = {}) const;

private:
    std::filesystem::path root_;
};

}  // namespace cutaway::gl
