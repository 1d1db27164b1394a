#include "gl/shader_library.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "gl/gl_error.h"

#ifndef CUTAWAY_SOURCE_SHADER_DIR
#define CUTAWAY_SOURCE_SHADER_DIR "shaders"
#endif

namespace cutaway::gl {
namespace {

constexpr int max_include_depth = 16;

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw GlError("shader file " + path.string() + ": cannot be read");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The quoted path of an `#include "path"` line, or empty if the line is not an include.
std::string include_target(const std::string& line) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line.compare(first, 8, "#include") != 0) return {};
    const auto open = line.find('"', first + 8);
    const auto close = open == std::string::npos ? open : line.find('"', open + 1);
    if (close == std::string::npos) return "\"";  // malformed: reported by the caller
    return line.substr(open + 1, close - open - 1);
}

std::string info_log(GLuint object, bool is_program) {
    GLint length = 0;
    if (is_program)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    if (is_program)
        glGetProgramInfoLog(object, length, nullptr, log.data());
    else
        glGetShaderInfoLog(object, length, nullptr, log.data());
    return log.c_str();
}

std::string file_legend(const ExpandedSource& source) {
    std::string legend;
    for (std::size_t i = 0; i < source.files.size(); ++i)
        legend += "  source " + std::to_string(i) + " = " + source.files[i].string() + "\n";
    return legend;
}

}  // namespace

ShaderLibrary::ShaderLibrary(std::filesystem::path root) : root_(std::move(root)) {
    if (!std::filesystem::is_directory(root_))
        throw GlError("shader folder " + root_.string() + ": not found (set CUTAWAY_SHADER_DIR to the shaders/ folder)");
}

std::filesystem::path ShaderLibrary::default_root() {
    if (const char* env = std::getenv("CUTAWAY_SHADER_DIR"); env != nullptr && *env != '\0') return env;
    return CUTAWAY_SOURCE_SHADER_DIR;
}

ExpandedSource ShaderLibrary::expand(const std::string& file, const ShaderDefines& defines) const {
    ExpandedSource out;
    std::vector<std::filesystem::path> stack;

    auto append = [&](auto&& self, const std::filesystem::path& path, bool is_top) -> void {
        if (std::find(stack.begin(), stack.end(), path) != stack.end())
            throw GlError("shader file " + path.string() + ": include cycle");
        if (int(stack.size()) >= max_include_depth)
            throw GlError("shader file " + path.string() + ": includes nested deeper than 16");
        stack.push_back(path);
        const std::size_t number = out.files.size();
        out.files.push_back(path);
        std::istringstream lines(read_text(path));
        std::string line;
        int line_number = 0;
        bool version_seen = !is_top;
        while (std::getline(lines, line)) {
            ++line_number;
            const std::string target = include_target(line);
            if (!target.empty()) {
                if (target == "\"")
                    throw GlError("shader file " + path.string() + ":" + std::to_string(line_number) +
                                  ": #include expects a quoted path");
                const std::filesystem::path included = root_ / target;
                if (!std::filesystem::exists(included))
                    throw GlError("shader file " + path.string() + ":" + std::to_string(line_number) +
                                  ": included file " + included.string() + " not found");
                self(self, included, false);
                out.text += "#line " + std::to_string(line_number + 1) + " " + std::to_string(number) + "\n";
                continue;
            }
            out.text += line + "\n";
            if (!version_seen && line.rfind("#version", 0) == 0) {
                version_seen = true;
                for (const auto& [name, value] : defines) out.text += "#define " + name + " " + value + "\n";
                out.text += "#line " + std::to_string(line_number + 1) + " " + std::to_string(number) + "\n";
            }
        }
        if (!version_seen) throw GlError("shader file " + path.string() + ": no #version line");
        stack.pop_back();
    };
    append(append, root_ / file, true);
    return out;
}

Program ShaderLibrary::build(const std::vector<ShaderStage>& stages, const ShaderDefines& defines) const {
    Program program(glCreateProgram());
    std::vector<Shader> shaders;
    std::string names;
    for (const ShaderStage& stage : stages) {
        const ExpandedSource source = expand(stage.file, defines);
        Shader shader(glCreateShader(stage.type));
        const char* text = source.text.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok)
            throw GlError("shader " + stage.file + " does not compile:\n" + info_log(shader.id(), false) +
                          file_legend(source));
        glAttachShader(program.id(), shader.id());
        shaders.push_back(std::move(shader));
        names += (names.empty() ? "" : " + ") + stage.file;
    }
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) throw GlError("shader program " + names + " does not link:\n" + info_log(program.id(), true));
    for (const Shader& shader : shaders) glDetachShader(program.id(), shader.id());
    return program;
}

}  // namespace cutaway::gl
